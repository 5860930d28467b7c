// Richardson extrapolation with the observed order. See richardson.hpp.
#include "study/richardson.hpp"

#include <cmath>
#include <cstdio>

namespace plyimpact::study {
namespace {

// (h1^p - h2^p) / (h2^p - h3^p) with the sizes scaled by h3 (overflow-safe for the p range used).
double ratio_for_order(double a, double b, double p) { return (std::pow(a, p) - std::pow(b, p)) / (std::pow(b, p) - 1); }

std::string band_text(double p, double lo, double hi) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "observed order %.3g outside the plausible band [%.3g, %.3g]", p, lo, hi);
  return buf;
}

}  // namespace

RichardsonResult richardson(const double h[3], const double q[3], double order_lo, double order_hi) {
  RichardsonResult r;
  r.order = r.value = std::nan("");
  r.ratio_coarse = h[0] / h[1];
  r.ratio_fine = h[1] / h[2];
  if (!(h[0] > h[1] && h[1] > h[2] && h[2] > 0)) {
    r.flags.push_back("mesh sizes are not strictly decreasing");
    return r;
  }
  const double d21 = q[0] - q[1], d32 = q[1] - q[2];
  if (d21 == 0 && d32 == 0) {
    r.flags.push_back("identical values on all three meshes: nothing to extrapolate");
    return r;
  }
  if (d32 == 0 || d21 == 0 || (d21 > 0) != (d32 > 0)) {
    r.flags.push_back("non-monotone differences (oscillatory convergence): no observed order");
    return r;
  }
  const double target = d21 / d32;  // > 0
  const double a = h[0] / h[2], b = h[1] / h[2];
  // Bisection on p in [1e-3, 50]: ratio_for_order rises from (a - b)/(b - 1) * ... monotonically.
  double lo = 1e-3, hi = 50;
  const double f_lo = ratio_for_order(a, b, lo) - target, f_hi = ratio_for_order(a, b, hi) - target;
  if (f_lo > 0 || f_hi < 0) {
    r.flags.push_back(f_lo > 0 ? "observed order below 0.001 (the error grows or barely shrinks)"
                               : "observed order above 50");
    return r;
  }
  for (int it = 0; it < 200 && hi - lo > 1e-13 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (ratio_for_order(a, b, mid) - target > 0 ? hi : lo) = mid;
  }
  r.order = 0.5 * (lo + hi);
  r.value = q[2] + (q[2] - q[1]) / (std::pow(b, r.order) - 1);
  r.extrapolated = true;
  r.asymptotic = r.order >= order_lo && r.order <= order_hi;
  if (!r.asymptotic) r.flags.push_back(band_text(r.order, order_lo, order_hi));
  return r;
}

}  // namespace plyimpact::study
