// ASTM D5528 reductions against corrected beam theory (beam_theory_dcb.hpp), an independent closed
// form: the data are C = k (a + Delta)^3 exactly and G = G_Ic at every crack length.
//
// Why the tolerances are what they are. MBT fits C^(1/3) = k^(1/3) a + k^(1/3) Delta, a straight
// line in a, so the fit is exact, its x-intercept is -Delta, and eq. 8.2 gives
// 3 P delta / (2 b (a + Delta)) = 3 P^2 k (a + Delta)^2 / (2 b) = P^2/(2b) dC/da = G_Ic. MCC fits
// a/h = C^(1/3) / (k^(1/3) h) - Delta/h, also exactly linear, so A1 = 1 / (k^(1/3) h) and eq. 8.5
// equals P^2/(2b) dC/da = G_Ic too. Both are therefore exact up to round-off: the tests ask
// 1e-10 relative (cbrt, log and an 11-point regression lose a few ulps; 1e-10 leaves 1e5 of them),
// far inside the 1 % the method is asked to meet on test data.
// CC assumes C = alpha a^n, which corrected beam theory is not when Delta != 0: ln C = ln k +
// 3 ln(a + Delta) has the local slope s(a) = 3 a / (a + Delta), falling from 3 a0/(a0 + Delta) to
// 3 a1/(a1 + Delta) over the data. The least-squares slope of a smooth curve is a positively
// weighted mean of its pairwise secant slopes, each equal to s at some point between (mean-value
// theorem); s grows with a (ds/da = 3 Delta / (a + Delta)^2 >= 0), so s(a0) <= n <= s(a1). And
// eq. 8.3 gives G_CC = n P^2 C / (2 b a) = G_Ic n (a + Delta) / (3 a): its bias is
// n (a + Delta)/(3 a) - 1, at most (s(a1) - s(a0)) / s(a0) in size. For Delta = 0.5 mm on 50-100 mm
// that bound is 0.5 % (CC within 1 %); for Delta = 4 mm it is 3.9 % and the largest bias of this
// data set is 2.2 %: CC is not within 1 % there, and the test checks the predicted bias instead.
#include <gtest/gtest.h>

#include <cmath>

#include "beam_theory_dcb.hpp"
#include "core/error.hpp"
#include "fracture/dcb_reduction.hpp"

namespace plyimpact {
namespace {

using fracture::reduce_dcb;
using test::BeamTheoryDcb;

constexpr double kRoundOff = 1e-10;  // relative; see the header comment

class DcbReductionExact : public ::testing::TestWithParam<double> {};  // parameter: Delta (m)

TEST_P(DcbReductionExact, MbtAndMccRecoverToughnessAndFits) {
  BeamTheoryDcb dcb;
  dcb.Delta = GetParam();
  const auto pts = dcb.propagation(50e-3, 100e-3, 5e-3);
  ASSERT_EQ(pts.size(), 11u);
  const auto r = reduce_dcb(pts, {dcb.width, dcb.thickness});
  EXPECT_NEAR(r.Delta, dcb.Delta, 1e-9) << "1 nm on 50 mm crack lengths";
  EXPECT_NEAR(r.delta_x_intercept, -dcb.Delta, 1e-9);
  const double A1 = 1.0 / (std::cbrt(dcb.k()) * dcb.thickness);
  EXPECT_NEAR(r.A1 / A1, 1.0, kRoundOff);
  EXPECT_NEAR(r.mcc_fit.intercept, -dcb.Delta / dcb.thickness, 1e-9 / dcb.thickness);
  EXPECT_NEAR(r.mbt_fit.slope / std::cbrt(dcb.k()), 1.0, kRoundOff);
  EXPECT_NEAR(r.mbt_fit.r2, 1.0, kRoundOff);
  EXPECT_NEAR(r.mcc_fit.r2, 1.0, kRoundOff);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(r.G_mbt[i] / dcb.G_Ic, 1.0, kRoundOff) << "a = " << pts[i].a;
    EXPECT_NEAR(r.G_mcc[i] / dcb.G_Ic, 1.0, kRoundOff) << "a = " << pts[i].a;
    EXPECT_NEAR(r.compliance[i] / (dcb.k() * std::pow(pts[i].a + dcb.Delta, 3)), 1.0, kRoundOff);
  }
}

TEST_P(DcbReductionExact, CcFollowsItsPredictedPowerLawBias) {
  BeamTheoryDcb dcb;
  dcb.Delta = GetParam();
  const double a0 = 50e-3, a1 = 100e-3;
  const auto pts = dcb.propagation(a0, a1, 5e-3);
  const auto r = reduce_dcb(pts, {dcb.width, dcb.thickness});
  const double s0 = 3 * a0 / (a0 + dcb.Delta), s1 = 3 * a1 / (a1 + dcb.Delta);
  EXPECT_GE(r.n, s0 * (1 - kRoundOff));
  EXPECT_LE(r.n, s1 * (1 + kRoundOff));
  const double bias_bound = (s1 - s0) / s0;
  double worst = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double predicted = dcb.G_Ic * r.n * (pts[i].a + dcb.Delta) / (3 * pts[i].a);
    EXPECT_NEAR(r.G_cc[i] / predicted, 1.0, kRoundOff) << "a = " << pts[i].a;
    worst = std::max(worst, std::abs(r.G_cc[i] / dcb.G_Ic - 1));
  }
  EXPECT_LE(worst, bias_bound + kRoundOff);
  if (bias_bound <= 0.01) {
    EXPECT_LE(worst, 0.01) << "CC within 1 % when the power-law bias allows it";
  }
  if (dcb.Delta == 0) {
    EXPECT_NEAR(r.n, 3.0, 1e-12);
  }
  std::printf("Delta = %.1f mm: n = %.6f (local slopes %.4f..%.4f), worst CC bias %.3f %% (bound %.3f %%)\n",
              dcb.Delta * 1e3, r.n, s0, s1, 100 * worst, 100 * bias_bound);
}

INSTANTIATE_TEST_SUITE_P(Delta, DcbReductionExact, ::testing::Values(0.0, 0.5e-3, 4e-3));

TEST(DcbReduction, LineFitOfKnownLine) {
  const double x[] = {1, 2, 3, 4}, y[] = {3, 5, 7, 9.5};
  const auto f = fracture::fit_line(x, y);
  // Normal equations by hand: mean x 2.5, mean y 6.125, Sxx 5, Sxy 10.75 -> slope 2.15,
  // intercept 6.125 - 2.15 * 2.5 = 0.75; residuals 0.1 -0.05 -0.2 0.15 -> SSres 0.075, SStot 23.1875.
  EXPECT_NEAR(f.slope, 2.15, 1e-14);
  EXPECT_NEAR(f.intercept, 0.75, 1e-14);
  EXPECT_NEAR(f.r2, 1 - 0.075 / 23.1875, 1e-14);
}

TEST(DcbReduction, RefusesTooFewPointsAndBadSpecimen) {
  BeamTheoryDcb dcb;
  const auto pts = dcb.propagation(50e-3, 55e-3, 5e-3);
  EXPECT_THROW(reduce_dcb(pts, {dcb.width, dcb.thickness}), InputError);
  const auto more = dcb.propagation(50e-3, 60e-3, 5e-3);
  EXPECT_THROW(reduce_dcb(more, {0.0, dcb.thickness}), InputError);
  EXPECT_THROW(reduce_dcb(more, {dcb.width, -1.0}), InputError);
  EXPECT_NO_THROW(reduce_dcb(more, {dcb.width, dcb.thickness}));
}

}  // namespace
}  // namespace plyimpact
