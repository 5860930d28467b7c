// The CFC filter against its closed-form response: a sine comes out scaled by
// G(f) = 1 / (1 + (tan(pi f T) / tan(pi T 2.0775 CFC))^4) with no phase shift (least-squares fit of
// sine and cosine over the middle of a 40 ms record, where the start's transient, a few 0.1 ms at
// CFC 600, is gone: tolerance 1e-6 of the amplitude); the corner where G = 1/sqrt(2) lies at the
// 1.65 CFC that SAE J211-1 states for the class (within 1.5 %: 1.667 CFC for T -> 0); a constant
// record passes unchanged to round-off; a symmetric pulse stays symmetric about its peak (zero phase).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "study/channel_filter.hpp"

namespace plyimpact::study {
namespace {

constexpr double kT = 5e-6;  // the scenes' history interval

struct Fit {
  double in_phase, quadrature;
};

// Least-squares a sin(wt) + b cos(wt) over samples [begin, end) of y.
Fit fit_sine(const std::vector<double>& y, double f, std::size_t begin, std::size_t end) {
  double ss = 0, cc = 0, sc = 0, ys = 0, yc = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const double w = 2 * std::numbers::pi * f * double(i) * kT;
    const double s = std::sin(w), c = std::cos(w);
    ss += s * s;
    cc += c * c;
    sc += s * c;
    ys += y[i] * s;
    yc += y[i] * c;
  }
  const double det = ss * cc - sc * sc;
  return {(ys * cc - yc * sc) / det, (yc * ss - ys * sc) / det};
}

TEST(ChannelFilter, SinesComeOutScaledByTheClosedFormGainWithoutPhase) {
  const std::size_t n = 8000;  // 40 ms
  for (double cfc : {180.0, 600.0, 1000.0}) {
    for (double f : {50.0, 250.0, 1000.0, 1650.0, 4000.0}) {
      std::vector<double> x(n);
      for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(2 * std::numbers::pi * f * double(i) * kT);
      const auto y = cfc_filter(x, kT, cfc);
      const Fit fit = fit_sine(y, f, n / 4, 3 * n / 4);
      EXPECT_NEAR(fit.in_phase, cfc_gain(f, kT, cfc), 1e-6) << "CFC " << cfc << ", " << f << " Hz";
      EXPECT_NEAR(fit.quadrature, 0, 1e-6) << "CFC " << cfc << ", " << f << " Hz";
    }
  }
}

TEST(ChannelFilter, CornerAtJ211sFrequency) {
  for (double cfc : {60.0, 180.0, 600.0, 1000.0}) {
    double lo = 0, hi = 10 * cfc;  // G falls monotonically: bisect G = 1/sqrt(2)
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      (cfc_gain(mid, kT, cfc) > 1 / std::numbers::sqrt2 ? lo : hi) = mid;
    }
    EXPECT_NEAR(lo / (1.65 * cfc), 1, 0.015) << "CFC " << cfc;
  }
  EXPECT_DOUBLE_EQ(cfc_gain(0, kT, 600), 1.0);
}

TEST(ChannelFilter, ConstantRecordPassesUnchanged) {
  // To round-off: the feedback coefficients sum to 1 - 4 a0, and at CFC 60 sampled every 5 us
  // a0 = 3.8e-6, so their rounding reaches the output amplified by about 1 / (4 a0) = 6.6e4.
  const std::vector<double> x(500, 3.25);
  for (double v : cfc_filter(x, kT, 60)) EXPECT_NEAR(v, 3.25, 3.25 * 1e-10);
}

TEST(ChannelFilter, SymmetricPulseStaysSymmetric) {
  // A 4 ms half-sine on a flat zero record, peak 1, as an impact force: its filtered peak stays at
  // the middle sample, and the record stays symmetric to round-off.
  const std::size_t n = 4001, mid = n / 2, half = 400;  // pulse: mid +- 2 ms
  std::vector<double> x(n, 0.0);
  for (std::size_t i = mid - half; i <= mid + half; ++i)
    x[i] = std::cos(std::numbers::pi * (double(i) - double(mid)) / double(2 * half));
  const auto y = cfc_filter(x, kT, 600);
  std::size_t peak = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (y[i] > y[peak]) peak = i;
  EXPECT_EQ(peak, mid);
  for (std::size_t k = 1; k < mid; ++k) EXPECT_NEAR(y[mid - k], y[mid + k], 1e-9) << k;
  // A 125 Hz pulse lies far below the 1 kHz corner: its peak is kept to within 1 %.
  EXPECT_NEAR(y[mid], 1.0, 0.01);
}

TEST(ChannelFilter, ShortRecordsAreReturnedUnchanged) {
  const std::vector<double> x{1.0, -2.0};
  EXPECT_EQ(cfc_filter(x, kT, 600), x);
}

}  // namespace
}  // namespace plyimpact::study
