// The C-scan raster (output/cscan) on layers whose delamination the raster cannot align with: a
// skewed, rotated mesh. A raster cell is misclassified only where the delamination's outline passes
// through it; a straight segment of length l crosses at most sqrt(2) l / p + 1 cells of side p, so
// for an outline of total length L made of k segments the union area is within
// p^2 (sqrt(2) L / p + k) = sqrt(2) L p + k p^2 of the exact one. Checked at two pitches, and the
// depth layering (shallowest, deepest, count) against the layers' own depths.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "output/cscan.hpp"

namespace plyimpact::output {
namespace {

// n x n parallelogram grid spanned by u and v from the origin; points inside the sub-parallelogram
// [a, b] x [a, b] (in grid units, on mid-lines) are delaminated.
CscanLayer skewed_layer(int id, double depth, int n, const double u[2], const double v[2], double a, double b) {
  CscanLayer l;
  l.id = id;
  l.depth = depth;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      l.xy.push_back(i * u[0] + j * v[0]);
      l.xy.push_back(i * u[1] + j * v[1]);
      l.delaminated.push_back(i > a && i < b && j > a && j < b);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int64_t p = j * (n + 1) + i;
      l.quads.insert(l.quads.end(), {p, p + 1, p + n + 2, p + n + 1});
    }
  return l;
}

TEST(Cscan, UnionAreaOfASkewedMeshWithinTheOutlineBound) {
  const double angle = 0.3, h = 1e-3;
  const double u[2] = {h * std::cos(angle), h * std::sin(angle)};
  const double v[2] = {h * (0.4 * std::cos(angle) - std::sin(angle)), h * (0.4 * std::sin(angle) + std::cos(angle))};
  const double cross = u[0] * v[1] - u[1] * v[0];  // area of one grid cell
  // Layer A delaminated on [2.5, 7.5]^2 grid units, layer B on [4.5, 9.5]^2 of the same grid: the
  // tributary regions are the sub-parallelograms between those mid-lines.
  const std::vector<CscanLayer> layers = {skewed_layer(1, 2e-3, 12, u, v, 2.5, 7.5),
                                          skewed_layer(2, 1e-3, 12, u, v, 4.5, 9.5)};
  const double a = 25 * cross, overlap = 9 * cross, exact = 2 * a - overlap;
  const double side_u = std::hypot(u[0], u[1]), side_v = std::hypot(v[0], v[1]);
  // Union outline: two squares of 5 x 5 cells less the 3 x 3 overlap's perimeter, 8 segments.
  const double outline = 2 * 10 * (side_u + side_v) - 6 * (side_u + side_v);
  for (const double p : {h / 8, h / 32}) {
    const CscanMap m = make_cscan(layers, p);
    const double bound = std::sqrt(2.0) * outline * p + 8 * p * p;
    EXPECT_NEAR(m.projected_area(), exact, bound) << "pitch " << p;
    int both = 0;
    for (std::size_t k = 0; k < m.count.size(); ++k) {
      if (m.count[k] == 0) {
        EXPECT_TRUE(std::isnan(m.shallowest[k]) && std::isnan(m.deepest[k]) && m.shallowest_id[k] == 0);
        continue;
      }
      both += m.count[k] == 2;
      EXPECT_EQ(m.shallowest_id[k] == 2, m.shallowest[k] == 1e-3);
      if (m.count[k] == 2) {
        EXPECT_EQ(m.shallowest[k], 1e-3) << "layer 2 is shallower and hides layer 1";
        EXPECT_EQ(m.deepest[k], 2e-3);
      }
    }
    EXPECT_NEAR(both * p * p, overlap, std::sqrt(2.0) * 6 * (side_u + side_v) * p + 4 * p * p);
  }
}

TEST(Cscan, AutomaticPitchIsHalfTheShortestEdgeWithinTheCellBudget) {
  const double u[2] = {1e-3, 0}, v[2] = {0, 0.5e-3};
  const std::vector<CscanLayer> layers = {skewed_layer(1, 0, 4, u, v, 0, 0)};
  EXPECT_DOUBLE_EQ(cscan_pitch(layers), 0.25e-3);
  // 4 mm x 2 mm with at most 8 cells: side sqrt(8 mm^2 / 8) = 1 mm.
  EXPECT_DOUBLE_EQ(cscan_pitch(layers, 8), 1e-3);
}

}  // namespace
}  // namespace plyimpact::output
