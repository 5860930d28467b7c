#include "material/plasticity.hpp"

#include <cmath>
#include <limits>

#include "core/voigt.hpp"

namespace plyimpact::material {

namespace {

double contract(const double a[6], const double b[6]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

// Piecewise-linear curve value and slope at x (constant beyond the last point).
void curve_at(const PlasticityParams& p, double x, double& value, double& slope, double& next_break) {
  const auto& e = p.curve_strain;
  const auto& s = p.curve_stress;
  next_break = std::numeric_limits<double>::infinity();
  if (x >= e.back()) {
    value = s.back(), slope = 0;
    return;
  }
  std::size_t i = 0;
  while (i + 1 < e.size() && e[i + 1] <= x) ++i;
  slope = (s[i + 1] - s[i]) / (e[i + 1] - e[i]);
  value = s[i] + slope * (x - e[i]);
  next_break = e[i + 1];
}

PlasticityParams elastic_part(double E, double PR) {
  PlasticityParams p;
  p.E = E, p.nu = PR;
  p.shear = E / (2 * (1 + PR));
  p.lambda = E * PR / ((1 + PR) * (1 - 2 * PR));
  return p;
}

}  // namespace

PlasticityParams plastic_kinematic(double E, double PR, double SIGY, double ETAN, double BETA, double SRC,
                                   double SRP, double FS) {
  PlasticityParams p = elastic_part(E, PR);
  p.sigy = SIGY;
  p.hardening = ETAN > 0 ? E * ETAN / (E - ETAN) : 0.0;
  p.beta = BETA;
  p.rate_c = SRC, p.rate_p = SRP;
  p.failure_strain = FS;
  return p;
}

PlasticityParams piecewise_linear(double E, double PR, double SIGY, double ETAN, double C, double P, double FAIL,
                                  const std::vector<double>& eps, const std::vector<double>& sig) {
  PlasticityParams p = elastic_part(E, PR);
  p.sigy = sig.empty() ? SIGY : sig.front();
  p.hardening = sig.empty() && ETAN > 0 ? E * ETAN / (E - ETAN) : 0.0;
  p.beta = 1.0;  // isotropic
  p.rate_c = C, p.rate_p = P;
  p.failure_strain = FAIL;
  p.curve_strain = eps;
  p.curve_stress = sig;
  return p;
}

double yield_stress(const PlasticityParams& p, double ep) {
  if (p.curve_strain.empty()) return p.sigy + p.beta * p.hardening * ep;
  double value, slope, next;
  curve_at(p, ep, value, slope, next);
  return value;
}

PlasticityResult plasticity_update(const PlasticityParams& p, const double R[9], const double D[6], double dt,
                                   double stress[6], double history[kPlasticityHistory]) {
  PlasticityResult result;
  double* alpha = history + 1;
  rotate_voigt(R, stress, stress);
  rotate_voigt(R, alpha, alpha);
  // Elastic trial stress.
  const double tr = (D[0] + D[1] + D[2]) * dt;
  for (int i = 0; i < 3; ++i) stress[i] += p.lambda * tr + 2 * p.shear * D[i] * dt;
  for (int i = 3; i < 6; ++i) stress[i] += 2 * p.shear * D[i] * dt;
  // Relative deviatoric stress xi = dev(sigma) - alpha and its von Mises measure.
  const double mean = (stress[0] + stress[1] + stress[2]) / 3.0;
  double xi[6];
  for (int i = 0; i < 6; ++i) xi[i] = stress[i] - (i < 3 ? mean : 0.0) - alpha[i];
  const double sbar = std::sqrt(1.5 * contract(xi, xi));
  // Cowper-Symonds scaling of the yield stress with the total strain-rate norm sqrt(D:D).
  const double rate = std::sqrt(contract(D, D));
  const double factor = p.rate_c > 0 && rate > 0 ? 1.0 + std::pow(rate / p.rate_c, 1.0 / p.rate_p) : 1.0;
  double& ep = history[0];
  const double G3 = 3 * p.shear;
  double dep = 0;
  if (p.curve_strain.empty()) {
    const double sy = factor * (p.sigy + p.beta * p.hardening * ep);
    if (sbar > sy) dep = (sbar - sy) / (G3 + (1 - p.beta) * p.hardening + factor * p.beta * p.hardening);
  } else {
    // Exact return on the piecewise-linear curve, segment by segment.
    double e = ep, value, slope, next;
    curve_at(p, e, value, slope, next);
    double residual = sbar - factor * value;
    while (residual > 0) {
      const double step = residual / (G3 + factor * slope);
      if (e + step <= next) {
        dep += step;
        break;
      }
      dep += next - e;
      residual -= (G3 + factor * slope) * (next - e);
      e = next;
      curve_at(p, e, value, slope, next);
    }
  }
  if (dep > 0) {
    const double scale = dep / sbar;  // along xi / sbar
    for (int i = 0; i < 6; ++i) {
      stress[i] -= G3 * scale * xi[i];
      alpha[i] += (1 - p.beta) * p.hardening * scale * xi[i];
    }
    ep += dep;
  }
  result.plastic_increment = dep;
  result.failed = p.failure_strain > 0 && ep >= p.failure_strain;
  return result;
}

}  // namespace plyimpact::material
