#include "mesh/hex_boundary.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "core/error.hpp"

namespace plyimpact::mesh {
namespace {

// The three edge neighbours of each corner, ordered so that the triple product is positive for a
// right-handed element (the same convention as element::hex8_corner_jacobians).
constexpr int kCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
// Faces of a right-handed hexahedron, counter-clockwise seen from outside (VTK's face order).
constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

double corner_triple(const std::vector<double>& x, const Index* c, int k) {
  const double* o = &x[3 * std::size_t(c[k])];
  double d[3][3];
  for (int m = 0; m < 3; ++m)
    for (int i = 0; i < 3; ++i) d[m][i] = x[3 * std::size_t(c[kCornerEdges[k][m]]) + i] - o[i];
  return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
}

}  // namespace

int orient_hexes(const std::vector<double>& coords, std::vector<Index>& hex) {
  int mirrored = 0;
  for (std::size_t e = 0; e < hex.size() / 8; ++e) {
    Index* c = &hex[8 * e];
    int positive = 0, negative = 0;
    for (int k = 0; k < 8; ++k) {
      const double t = corner_triple(coords, c, k);
      positive += t > 0;
      negative += t < 0;
    }
    if (negative == 8) {
      std::swap(c[1], c[3]);
      std::swap(c[5], c[7]);
      ++mirrored;
    } else if (positive != 8) {
      throw InputError(msg() << "meshing failed: hexahedron " << e << " is tangled (" << positive
                             << " positive and " << negative << " negative corner Jacobians)");
    }
  }
  return mirrored;
}

std::vector<Index> boundary_quads(const std::vector<Index>& hex) {
  // Key: the face's sorted nodes; value: (uses, first element * 6 + face).
  std::map<std::array<Index, 4>, std::pair<int, std::size_t>> faces;
  for (std::size_t e = 0; e < hex.size() / 8; ++e)
    for (int f = 0; f < 6; ++f) {
      std::array<Index, 4> key;
      for (int k = 0; k < 4; ++k) key[k] = hex[8 * e + kFaces[f][k]];
      std::sort(key.begin(), key.end());
      auto [it, fresh] = faces.try_emplace(key, 0, 6 * e + std::size_t(f));
      ++it->second.first;
    }
  std::vector<std::size_t> once;
  for (const auto& [key, use] : faces)
    if (use.first == 1) once.push_back(use.second);
  std::sort(once.begin(), once.end());
  std::vector<Index> quads;
  quads.reserve(4 * once.size());
  for (std::size_t ef : once)
    for (int k = 0; k < 4; ++k) quads.push_back(hex[8 * (ef / 6) + kFaces[ef % 6][k]]);
  return quads;
}

}  // namespace plyimpact::mesh
