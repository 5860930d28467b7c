// Lambert-Jonas fit. See lambert_jonas.hpp.
#include "study/lambert_jonas.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace plyimpact::study {
namespace {

double shape(double v, double v_bl, double p) {
  return v > v_bl ? std::pow(std::pow(v, p) - std::pow(v_bl, p), 1.0 / p) : 0.0;
}

// Best a for (v_bl, p) and the resulting sum of squared residuals.
LambertJonasFit best_for(std::span<const double> v, const std::vector<double>& vr, double v_bl, double p) {
  double gg = 0, gy = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double g = shape(v[i], v_bl, p);
    gg += g * g;
    gy += g * vr[i];
  }
  LambertJonasFit f{gg > 0 ? std::max(0.0, gy / gg) : 0.0, p, v_bl, 0};
  double sse = 0;
  for (std::size_t i = 0; i < v.size(); ++i) sse += std::pow(f.a * shape(v[i], v_bl, p) - vr[i], 2);
  f.rms = std::sqrt(sse / double(v.size()));
  return f;
}

}  // namespace

double lambert_jonas(const LambertJonasFit& fit, double v) { return fit.a * shape(v, fit.v_bl, fit.p); }

LambertJonasFit fit_lambert_jonas(std::span<const double> velocity, std::span<const double> residual) {
  if (velocity.size() != residual.size() || velocity.size() < 3)
    throw InputError(msg() << "Lambert-Jonas fit: " << velocity.size() << " points; allowed at least 3 (v, v_r) pairs");
  std::vector<double> vr(residual.begin(), residual.end());
  for (double& x : vr) x = std::max(0.0, x);
  const auto perforated = std::count_if(vr.begin(), vr.end(), [](double x) { return x > 0; });
  if (perforated < 2)
    throw InputError(msg() << "Lambert-Jonas fit: " << perforated
                           << " perforating cases; allowed a sweep with at least 2 velocities above the ballistic limit");
  const double v_max = *std::max_element(velocity.begin(), velocity.end());
  double bl_lo = 0, bl_hi = v_max, p_lo = 1, p_hi = 10;
  LambertJonasFit best = best_for(velocity, vr, 0, 2);
  constexpr int kGrid = 40;
  for (int zoom = 0; zoom < 8; ++zoom) {
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; j <= kGrid; ++j) {
        const double bl = bl_lo + (bl_hi - bl_lo) * i / kGrid, p = p_lo + (p_hi - p_lo) * j / kGrid;
        const LambertJonasFit f = best_for(velocity, vr, std::min(bl, v_max * (1 - 1e-9)), p);
        if (f.rms < best.rms) best = f;
      }
    // Zoom in around the best point: a quarter of the current span each way, kept in bounds.
    const double dbl = (bl_hi - bl_lo) / 4, dp = (p_hi - p_lo) / 4;
    bl_lo = std::max(0.0, best.v_bl - dbl);
    bl_hi = std::min(v_max, best.v_bl + dbl);
    p_lo = std::max(1.0, best.p - dp);
    p_hi = std::min(10.0, best.p + dp);
  }
  return best;
}

}  // namespace plyimpact::study
