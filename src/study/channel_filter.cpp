// CFC filtering. See channel_filter.hpp.
#include "study/channel_filter.hpp"

#include <cmath>
#include <numbers>

namespace plyimpact::study {
namespace {

struct Biquad {
  double a0, a1, a2, b1, b2;  // y[n] = a0 x[n] + a1 x[n-1] + a2 x[n-2] + b1 y[n-1] + b2 y[n-2]
};

double prewarped_corner(double sample_interval, double cfc) {
  return std::tan(std::numbers::pi * sample_interval * 2.0775 * cfc);
}

Biquad design(double sample_interval, double cfc) {
  const double wa = prewarped_corner(sample_interval, cfc);
  const double d = 1 + std::numbers::sqrt2 * wa + wa * wa;
  const double a0 = wa * wa / d;
  return {a0, 2 * a0, a0, -2 * (wa * wa - 1) / d, (-1 + std::numbers::sqrt2 * wa - wa * wa) / d};
}

// One pass in place, from the steady state of the first value (the filter's DC gain is one, so
// inputs and outputs before the record are all equal to it).
void run_pass(const Biquad& f, std::vector<double>& v) {
  double x1 = v.front(), x2 = v.front(), y1 = v.front(), y2 = v.front();
  for (double& s : v) {
    const double x = s;
    const double y = f.a0 * x + f.a1 * x1 + f.a2 * x2 + f.b1 * y1 + f.b2 * y2;
    x2 = x1;
    x1 = x;
    y2 = y1;
    y1 = y;
    s = y;
  }
}

}  // namespace

std::vector<double> cfc_filter(std::span<const double> x, double sample_interval, double cfc) {
  std::vector<double> v(x.begin(), x.end());
  if (v.size() < 3) return v;
  const Biquad f = design(sample_interval, cfc);
  run_pass(f, v);
  std::vector<double> back(v.rbegin(), v.rend());
  run_pass(f, back);
  return {back.rbegin(), back.rend()};
}

double cfc_gain(double f, double sample_interval, double cfc) {
  const double ratio = std::tan(std::numbers::pi * f * sample_interval) / prewarped_corner(sample_interval, cfc);
  return 1 / (1 + std::pow(ratio, 4));
}

}  // namespace plyimpact::study
