// 1-D node distributions: band layout, exact break points, grading, and nesting of refinement
// levels h, h/2, h/4 bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/axis_grid.hpp"

using namespace plyimpact::mesh;

namespace {
AxisSpec d7136_x(int level) {
  AxisSpec s;
  s.lo = 0;
  s.hi = 0.150;
  s.breaks = {0.0125, 0.1375};        // window edges
  s.zone_lo = 0.060;
  s.zone_hi = 0.090;                   // 30 mm zone
  s.size = 0.005;
  s.zone_size = 0.00125;
  s.level = level;
  return s;
}
}  // namespace

TEST(AxisGrid, UniformAxisCountsAndEnds) {
  AxisSpec s;
  s.hi = 0.150;
  s.size = 0.004;  // 37.5 -> 38 elements
  const auto bands = axis_bands(s);
  ASSERT_EQ(bands.size(), 1u);
  EXPECT_EQ(bands[0].elements, 38);
  const auto x = band_nodes(bands);
  ASSERT_EQ(x.size(), 39u);
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_EQ(x.back(), 0.150);
}

TEST(AxisGrid, BreakPointsAreExactNodesAndZoneIsUniform) {
  const auto bands = axis_bands(d7136_x(0));
  ASSERT_EQ(bands.size(), 5u);  // edge | window..zone (graded) | zone | zone..window (graded) | edge
  EXPECT_EQ(bands[0].elements, 3);   // 12.5 mm at 5 mm
  EXPECT_EQ(bands[2].elements, 24);  // 30 mm at 1.25 mm
  EXPECT_EQ(bands[2].ratio, 1.0);
  EXPECT_GT(bands[3].ratio, 1.0);                        // grows away from the zone
  EXPECT_DOUBLE_EQ(bands[1].ratio, 1.0 / bands[3].ratio);  // mirror image
  const auto x = band_nodes(bands);
  for (double b : {0.0125, 0.060, 0.090, 0.1375}) EXPECT_NE(std::find(x.begin(), x.end(), b), x.end()) << b;
  // Graded band: first element next to the zone has the zone size, the last is at most the plate size.
  const auto at = std::find(x.begin(), x.end(), 0.090) - x.begin();
  EXPECT_NEAR(x[at + 1] - x[at], 0.00125, 1e-12);
  const auto w = std::find(x.begin(), x.end(), 0.1375) - x.begin();
  EXPECT_LE(x[w] - x[w - 1], 0.005 * (1 + 1e-9));
  EXPECT_GT(x[w] - x[w - 1], 0.004);
  for (std::size_t i = 1; i < x.size(); ++i) EXPECT_GT(x[i], x[i - 1]);
}

TEST(AxisGrid, RefinementLevelsNestBitForBit) {
  const auto x0 = band_nodes(axis_bands(d7136_x(0)));
  const auto x1 = band_nodes(axis_bands(d7136_x(1)));
  const auto x2 = band_nodes(axis_bands(d7136_x(2)));
  ASSERT_EQ(x1.size() - 1, 2 * (x0.size() - 1));
  ASSERT_EQ(x2.size() - 1, 4 * (x0.size() - 1));
  for (std::size_t i = 0; i < x0.size(); ++i) {
    EXPECT_EQ(x1[2 * i], x0[i]) << i;
    EXPECT_EQ(x2[4 * i], x0[i]) << i;
  }
  for (std::size_t i = 0; i < x1.size(); ++i) EXPECT_EQ(x2[2 * i], x1[i]) << i;
}
