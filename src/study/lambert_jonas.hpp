// Lambert-Jonas residual-velocity curve of a perforation sweep (Lambert and Jonas, "Towards
// standard perforation test correlations for small arms ...", BRL Report 1852, 1976; as used by
// Recht and Ipson for rigid projectiles):
//   v_r = a (v^p - v_bl^p)^(1/p)  for v > v_bl,   v_r = 0  otherwise,
// with v_bl the ballistic limit. Fitted by least squares on (v, v_r) pairs (v_r <= 0, a stopped or
// rebounding projectile, counts as 0): for fixed (v_bl, p) the best a is linear (closed form), and
// (v_bl, p) are found by a global grid search refined by successive zooms, so no starting guess is
// needed and the fit cannot wander off to a local minimum far from the data. p is searched in
// [1, 10] (the model's physical range; p = 2 is Recht-Ipson), v_bl in [0, max v].
#pragma once

#include <span>

namespace plyimpact::study {

struct LambertJonasFit {
  double a = 0, p = 0, v_bl = 0;
  double rms = 0;  // root-mean-square residual of v_r (m/s)
};

/// Model value at impact velocity v.
double lambert_jonas(const LambertJonasFit& fit, double v);

/// Fits the curve. @throws InputError with fewer than 3 points or fewer than 2 perforations
LambertJonasFit fit_lambert_jonas(std::span<const double> velocity, std::span<const double> residual);

}  // namespace plyimpact::study
