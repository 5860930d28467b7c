// Richardson extrapolation on manufactured sequences q(h) = q* + C h^p with an exact answer: the
// observed order and q* are recovered to round-off (tolerance 1e-9, the bisection stops at 1e-13
// relative), for constant and for varying refinement ratios; sequences outside the asymptotic
// range are flagged instead of extrapolated.
#include <gtest/gtest.h>

#include <cmath>

#include "study/richardson.hpp"

namespace plyimpact::study {
namespace {

RichardsonResult manufactured(double q_star, double c, double p, const double h[3], double lo = 0.5, double hi = 4) {
  const double q[3] = {q_star + c * std::pow(h[0], p), q_star + c * std::pow(h[1], p), q_star + c * std::pow(h[2], p)};
  return richardson(h, q, lo, hi);
}

TEST(Richardson, RecoversOrderAndLimitForConstantRatio) {
  const double h[3] = {0.4, 0.2, 0.1};
  const auto r = manufactured(3.0, 0.7, 1.7, h);
  ASSERT_TRUE(r.extrapolated);
  EXPECT_NEAR(r.order, 1.7, 1e-9);
  EXPECT_NEAR(r.value, 3.0, 1e-9);
  EXPECT_TRUE(r.asymptotic);
  EXPECT_TRUE(r.flags.empty());
  // The closed form for a constant ratio.
  const double q[3] = {3 + 0.7 * std::pow(0.4, 1.7), 3 + 0.7 * std::pow(0.2, 1.7), 3 + 0.7 * std::pow(0.1, 1.7)};
  EXPECT_NEAR(r.order, std::log((q[0] - q[1]) / (q[1] - q[2])) / std::log(2.0), 1e-9);
}

TEST(Richardson, RecoversOrderForVaryingRatios) {
  const double h[3] = {1.0, 0.6, 0.25};  // ratios 1.67 and 2.4
  const auto r = manufactured(-12.5, -4.0, 2.3, h);
  ASSERT_TRUE(r.extrapolated);
  EXPECT_NEAR(r.order, 2.3, 1e-9);
  EXPECT_NEAR(r.value, -12.5, 1e-9);
  EXPECT_NEAR(r.ratio_coarse, 1.0 / 0.6, 1e-15);
  EXPECT_NEAR(r.ratio_fine, 2.4, 1e-15);
}

TEST(Richardson, FlagsSequencesOutsideTheAsymptoticRange) {
  const double h[3] = {0.4, 0.2, 0.1};
  const double oscillating[3] = {1.0, 1.2, 1.1};
  const auto o = richardson(h, oscillating, 0.5, 4);
  EXPECT_FALSE(o.extrapolated);
  ASSERT_FALSE(o.flags.empty());
  EXPECT_NE(o.flags[0].find("non-monotone"), std::string::npos);
  const auto high = manufactured(1.0, 1.0, 6.0, h);  // converges, but faster than the band allows
  EXPECT_TRUE(high.extrapolated);
  EXPECT_FALSE(high.asymptotic);
  EXPECT_NEAR(high.order, 6.0, 1e-9);
  ASSERT_FALSE(high.flags.empty());
  EXPECT_NE(high.flags[0].find("outside the plausible band"), std::string::npos);
  const double flat[3] = {2, 2, 2};
  EXPECT_FALSE(richardson(h, flat, 0.5, 4).extrapolated);
}

}  // namespace
}  // namespace plyimpact::study
