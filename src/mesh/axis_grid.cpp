#include "mesh/axis_grid.hpp"

#include <algorithm>
#include <cmath>

namespace plyimpact::mesh {
namespace {

// Ratio r > 1 with a (r^n - 1)/(r - 1) = l (n elements, first size a, total l > n a), by bisection.
double progression_ratio(double a, double l, int n) {
  double lo = 1.0, hi = 2.0;
  auto total = [&](double r) { return a * (std::pow(r, n) - 1) / (r - 1); };
  while (total(hi) < l) hi *= 2;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (total(mid) < l ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// A band of length l growing from size a (at its zone end) to about b.
Band graded(double l, double a, double b) {
  Band band;
  if (l <= b || b <= a * (1 + 1e-9)) {
    band.elements = std::max(1, int(std::ceil(l / b - 1e-9)));
    return band;
  }
  const double r = (l - a) / (l - b);  // growth that reaches b exactly at the far end
  // Round the count up: a slightly smaller ratio keeps the last element within b.
  const int n = std::max(1, int(std::ceil(std::log(b / a) / std::log(r) - 1e-9)) + 1);
  band.elements = n;
  band.ratio = n * a >= l ? 1.0 : progression_ratio(a, l, n);
  return band;
}

}  // namespace

std::vector<Band> axis_bands(const AxisSpec& s) {
  const double tol = 1e-9 * (s.hi - s.lo);
  const bool zone = s.zone_hi > s.zone_lo && s.zone_size > 0;
  std::vector<double> pts{s.lo, s.hi};
  for (double b : s.breaks) pts.push_back(b);
  if (zone) pts.insert(pts.end(), {s.zone_lo, s.zone_hi});
  std::erase_if(pts, [&](double p) { return p < s.lo || p > s.hi; });
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end(), [&](double a, double b) { return b - a <= tol; }), pts.end());
  pts.front() = s.lo;
  pts.back() = s.hi;

  std::vector<Band> bands;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double x0 = pts[i], x1 = pts[i + 1], l = x1 - x0;
    Band b;
    if (zone && x0 >= s.zone_lo - tol && x1 <= s.zone_hi + tol) {
      b.elements = std::max(1, int(std::ceil(l / s.zone_size - 1e-9)));
    } else if (zone && std::abs(x0 - s.zone_hi) <= tol) {
      b = graded(l, s.zone_size, s.size);  // grows away from the zone, towards x1
    } else if (zone && std::abs(x1 - s.zone_lo) <= tol) {
      b = graded(l, s.zone_size, s.size);
      b.ratio = 1 / b.ratio;  // grows towards x0
    } else {
      b.elements = std::max(1, int(std::ceil(l / s.size - 1e-9)));
    }
    b.x0 = x0;
    b.x1 = x1;
    const int k = 1 << s.level;
    b.base_elements = b.elements;
    b.base_ratio = b.ratio;
    b.elements *= k;
    b.ratio = std::pow(b.ratio, 1.0 / k);
    bands.push_back(b);
  }
  return bands;
}

std::vector<double> band_nodes(const std::vector<Band>& bands) {
  std::vector<double> x;
  for (const Band& b : bands) {
    if (x.empty()) x.push_back(b.x0);
    // Level 0, sizes a r^j: node j at x0 + l (r^j - 1)/(r^n - 1) (uniform when r = 1). Level k
    // evaluates the same formula at t = j / 2^k, exact in binary for the coarse nodes.
    const int n = b.base_elements, k = b.elements / b.base_elements;
    const double r = b.base_ratio, rn = std::pow(r, n);
    for (int j = 1; j < b.elements; ++j) {
      const double t = double(j) / k;
      const double f = r == 1.0 ? t / n : (std::pow(r, t) - 1) / (rn - 1);
      x.push_back(b.x0 + (b.x1 - b.x0) * f);
    }
    x.push_back(b.x1);
  }
  return x;
}

}  // namespace plyimpact::mesh
