// Lambert-Jonas fit on synthetic perforation data drawn from the model itself (a = 0.9, p = 2.5,
// v_bl = 300 m/s, 11 velocities 200-700 m/s with 3 below the limit): exact data give the
// parameters back to the search's resolution (the zoomed grid resolves v_bl to ~0.05 m/s and p to
// ~1e-3; tolerances 0.5 m/s, 0.02, 0.005). With +-2 m/s of alternating noise on v_r (about 0.5 %
// of the residual velocities) the ballistic limit stays within 2 % and the rms residual near 2.
#include <gtest/gtest.h>

#include <vector>

#include "core/error.hpp"
#include "study/lambert_jonas.hpp"

namespace plyimpact::study {
namespace {

TEST(LambertJonas, RecoversKnownParameters) {
  const LambertJonasFit truth{0.9, 2.5, 300, 0};
  std::vector<double> v, vr, noisy;
  for (double x = 200; x <= 700; x += 50) {
    v.push_back(x);
    vr.push_back(lambert_jonas(truth, x));
    noisy.push_back(vr.back() > 0 ? vr.back() + (v.size() % 2 ? 2.0 : -2.0) : 0.0);
  }
  const auto fit = fit_lambert_jonas(v, vr);
  EXPECT_NEAR(fit.v_bl, 300, 0.5);
  EXPECT_NEAR(fit.p, 2.5, 0.02);
  EXPECT_NEAR(fit.a, 0.9, 0.005);
  EXPECT_LT(fit.rms, 0.1);
  const auto nf = fit_lambert_jonas(v, noisy);
  EXPECT_NEAR(nf.v_bl, 300, 6);
  EXPECT_LT(nf.rms, 2.5);
}

TEST(LambertJonas, ReboundsCountAsStoppedAndTooFewPerforationsAreRefused) {
  const std::vector<double> v{100, 200, 300}, vr{-20, -5, 10};
  EXPECT_THROW(fit_lambert_jonas(v, vr), InputError);  // one perforation only
}

}  // namespace
}  // namespace plyimpact::study
