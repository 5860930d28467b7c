// Hexahedron orientation and boundary extraction on hand-built meshes: a left-handed element is
// mirrored into LS-DYNA/VTK order, a tangled one is refused, and two unit cubes sharing a face have
// 10 boundary quads, each outward (its normal points away from the element it belongs to).
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "element/hex8.hpp"
#include "mesh/hex_boundary.hpp"

using namespace plyimpact;

namespace {

// Two unit cubes side by side along x: nodes (i, j, k), i = 0..2, j, k = 0..1, index i + 3 j + 6 k.
std::vector<double> coords() {
  std::vector<double> x;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) x.insert(x.end(), {double(i), double(j), double(k)});
  return x;
}

std::vector<Index> cube(Index i) { return {i, i + 1, i + 4, i + 3, i + 6, i + 7, i + 10, i + 9}; }

}  // namespace

TEST(HexBoundary, MirrorsLeftHandedAndRefusesTangled) {
  const auto x = coords();
  std::vector<Index> hex = cube(0);
  const auto good = cube(1);
  hex.insert(hex.end(), {good[0], good[3], good[2], good[1], good[4], good[7], good[6], good[5]});  // mirrored
  EXPECT_EQ(mesh::orient_hexes(x, hex), 1);
  for (std::size_t e = 0; e < 2; ++e) {
    double xe[3][8], detj[8];
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i) xe[i][k] = x[3 * std::size_t(hex[8 * e + k]) + i];
    element::hex8_corner_jacobians(xe, detj);
    for (double d : detj) EXPECT_NEAR(d, 0.125, 1e-15);  // unit cube: det J = (1/2)^3 everywhere
  }
  std::vector<Index> tangled = cube(0);
  std::swap(tangled[6], tangled[7]);  // twists the top face: corners of both signs
  EXPECT_THROW(mesh::orient_hexes(x, tangled), InputError);
}

TEST(HexBoundary, TwoCubesHaveTenOutwardQuads) {
  const auto x = coords();
  std::vector<Index> hex = cube(0);
  const auto second = cube(1);
  hex.insert(hex.end(), second.begin(), second.end());
  const auto quads = mesh::boundary_quads(hex);
  ASSERT_EQ(quads.size(), 40u);
  for (std::size_t q = 0; q < 10; ++q) {
    const Index* c = &quads[4 * q];
    double centre[3] = {0, 0, 0}, d1[3], d2[3];
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 4; ++k) centre[i] += x[3 * std::size_t(c[k]) + i] / 4;
      d1[i] = x[3 * std::size_t(c[2]) + i] - x[3 * std::size_t(c[0]) + i];
      d2[i] = x[3 * std::size_t(c[3]) + i] - x[3 * std::size_t(c[1]) + i];
    }
    const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
    // The shared face x = 1 is interior and must not appear; every other face points away from the
    // centre of its own cube (x = 0.5 or 1.5, y = z = 0.5).
    EXPECT_FALSE(centre[0] == 1.0 && n[1] == 0 && n[2] == 0) << "interior face " << q;
    const double own_x = centre[0] < 1 ? 0.5 : 1.5;  // lateral faces: centre x = 0.5 or 1.5
    const double out[3] = {centre[0] - own_x, centre[1] - 0.5, centre[2] - 0.5};
    EXPECT_GT(n[0] * out[0] + n[1] * out[1] + n[2] * out[2], 0.0) << "quad " << q;
  }
}
