#include "material/johnson_cook.hpp"

#include <algorithm>
#include <cmath>

#include "core/voigt.hpp"

namespace plyimpact::material {

namespace {

using namespace jc_history;

double contract(const double a[6], const double b[6]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

// Largest principal value of a symmetric tensor (Voigt), by the trigonometric solution of the
// characteristic cubic (Smith, Comm. ACM 4(4), 1961).
double max_principal(const double s[6]) {
  const double m = (s[0] + s[1] + s[2]) / 3;
  const double a = s[0] - m, b = s[1] - m, c = s[2] - m;
  const double J2 = 0.5 * (a * a + b * b + c * c) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  if (J2 <= 0) return m;
  const double J3 = a * b * c + 2 * s[3] * s[4] * s[5] - a * s[4] * s[4] - b * s[5] * s[5] - c * s[3] * s[3];
  const double r = std::clamp(J3 / 2 * std::pow(3 / J2, 1.5), -1.0, 1.0);
  return m + 2 * std::sqrt(J2 / 3) * std::cos(std::acos(r) / 3);
}

// Rate term 1 + C ln(rate*), no effect below the reference rate (the log would soften).
double rate_factor(const JohnsonCookParams& p, double rate_star) {
  return p.C != 0 && rate_star > 1 ? 1 + p.C * std::log(rate_star) : 1.0;
}

// Plastic increment dep of the radial return: sbar_trial - 3 G dep = sigma_y(ep + dep, rate, T).
// g(dep) = sbar_trial - 3 G dep - sigma_y decreases in dep (sigma_y does not decrease), g(0) > 0,
// and g(dep0) <= 0 at the perfectly plastic estimate dep0 = (sbar_trial - sigma_y(ep)) / 3G: Newton
// steps inside that bracket, bisection when a step would leave it.
double return_increment(const JohnsonCookParams& p, double sbar, double ep, double total_rate_star, double T_star,
                        double dt, double& sigma_y) {
  const double G3 = 3 * p.shear;
  auto rate_of = [&](double dep) { return p.VP == 1 ? dep / (dt * p.EPSO) : total_rate_star; };
  auto g = [&](double dep, double& slope) {
    const double e = ep + dep;
    const double r = rate_of(dep);
    const double sy = johnson_cook_flow_stress(p, e, r, T_star);
    // d sigma_y / d dep, by a one-sided difference scaled to the increment (the power law has an
    // infinite slope at e = 0, the log at dep = 0; the bracket keeps Newton safe there).
    const double h = std::max(1e-7 * (e + dep), 1e-14);
    const double dsy = (johnson_cook_flow_stress(p, e + h, p.VP == 1 ? rate_of(dep + h) : r, T_star) - sy) / h;
    slope = -G3 - dsy;
    sigma_y = sy;
    return sbar - G3 * dep - sy;
  };
  double lo = 0, hi = (sbar - johnson_cook_flow_stress(p, ep, rate_of(0), T_star)) / G3;
  double slope;
  if (g(hi, slope) >= 0) return hi;  // flat flow stress: the estimate is exact
  double x = hi;
  for (int it = 0; it < 60; ++it) {
    const double gx = g(x, slope);
    if (std::abs(gx) <= 1e-12 * sbar) return x;
    (gx > 0 ? lo : hi) = x;
    double next = x - gx / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 1e-15 * std::max(hi, 1e-30)) {
      g(next, slope);  // sigma_y of the returned increment
      return next;
    }
    x = next;
  }
  g(x, slope);
  return x;
}

}  // namespace

double homologous_temperature(const JohnsonCookParams& p, double temperature_rise) {
  if (!p.thermal()) return 0;
  return std::clamp(temperature_rise / (p.TM - p.TR), 0.0, 1.0);
}

double johnson_cook_flow_stress(const JohnsonCookParams& p, double ep, double rate_star, double T_star) {
  const double hardening = std::min(p.A + (ep > 0 ? p.B * std::pow(ep, p.N) : 0.0), p.SIGMAX);
  const double thermal = T_star > 0 ? 1 - std::pow(T_star, p.M) : 1.0;
  return std::min(hardening * rate_factor(p, rate_star), p.SIGSAT) * thermal;
}

double johnson_cook_fracture_strain(const JohnsonCookParams& p, double triaxiality, double rate_star, double T_star) {
  const double log_rate = rate_star > 1 ? std::log(rate_star) : 0.0;
  const double ef = (p.D1 + p.D2 * std::exp(p.D3 * triaxiality)) * (1 + p.D4 * log_rate) * (1 + p.D5 * T_star);
  return std::max(ef, p.EFMIN);
}

JohnsonCookResult johnson_cook_update(const JohnsonCookParams& p, const double R[9], const double D[6], double dt,
                                      double stress[6], double h[kJohnsonCookHistory]) {
  JohnsonCookResult result;
  rotate_voigt(R, stress, stress);
  const double p_old = -(stress[0] + stress[1] + stress[2]) / 3;
  const double trD = D[0] + D[1] + D[2];
  double Dd[6], s_old[6], s[6];
  for (int i = 0; i < 6; ++i) {
    Dd[i] = D[i] - (i < 3 ? trD / 3 : 0.0);
    s_old[i] = stress[i] + (i < 3 ? p_old : 0.0);
    s[i] = s_old[i] + 2 * p.shear * Dd[i] * dt;
  }
  const double V_old = std::exp(h[kLogVolume]);
  h[kLogVolume] += trD * dt;
  const double V = std::exp(h[kLogVolume]);
  const bool failed_before = h[kFailed] != 0;

  // Deviatoric return.
  const double T_star = homologous_temperature(p, h[kTemperatureRise]);
  const double rate_star = std::sqrt(2.0 / 3.0 * contract(Dd, Dd)) / p.EPSO;
  double& ep = h[kPlasticStrain];
  double dep = 0, sigma_y = 0;
  if (failed_before) {
    std::fill(s, s + 6, 0.0);
  } else if (dt > 0) {
    const double sbar = std::sqrt(1.5 * contract(s, s));
    const double sy0 = johnson_cook_flow_stress(p, ep, p.VP == 1 ? 0.0 : rate_star, T_star);
    if (sbar > sy0) {
      dep = return_increment(p, sbar, ep, rate_star, T_star, dt, sigma_y);
      const double scale = 1 - 3 * p.shear * dep / sbar;
      for (double& v : s) v *= scale;
      ep += dep;
    }
  }
  // Plastic work per current volume with the trapezoid rule on the effective stress (the rule of
  // the element's stress work, so stress work = elastic energy + plastic work holds step by step);
  // per reference volume times V. Its TQC share heats.
  const double work = dep > 0 ? 0.5 * (std::sqrt(1.5 * contract(s_old, s_old)) + sigma_y) * dep * V : 0.0;
  h[kPlasticWork] += work;
  if (p.thermal()) h[kTemperatureRise] += p.TQC * work / (p.rho0 * p.CP);

  // Pressure: the EOS with the energy of this step closed exactly (p is linear in E), or K.
  double pressure;
  if (p.eos.kind != EosParams::Kind::None) {
    double sDd = 0;
    for (int i = 0; i < 6; ++i) sDd += 0.5 * (s_old[i] + s[i]) * Dd[i] * (i < 3 ? 1.0 : 2.0);
    const double dV = V - V_old;
    const double E_star = h[kEnergy] + 0.5 * (V + V_old) * sDd * dt - 0.5 * p_old * dV;
    double a, b;
    eos_coefficients(p.eos, 1 / V - 1, a, b);
    pressure = (a + b * (E_star + p.eos.E0)) / (1 + 0.5 * b * dV);
    h[kEnergy] = E_star - 0.5 * pressure * dV;
  } else {
    pressure = p_old - p.bulk * trD * dt;
  }

  // Tension limits and spall.
  if (failed_before) {
    pressure = std::max(pressure, 0.0);
  } else if (p.PC < 0) {
    if (p.SPALL == 1) {
      pressure = std::max(pressure, p.PC);
    } else {
      double trial[6];
      for (int i = 0; i < 6; ++i) trial[i] = s[i] - (i < 3 ? pressure : 0.0);
      const bool spall = p.SPALL == 3 ? pressure < p.PC : max_principal(trial) >= -p.PC;
      if (spall) {
        h[kFailed] = 1;
        std::fill(s, s + 6, 0.0);
        pressure = std::max(pressure, 0.0);
      }
    }
  }

  // Failure: Johnson-Cook damage (MAT_015) or PSFAIL (MAT_098).
  if (dep > 0 && p.damage()) {
    const double triaxiality = -pressure / sigma_y;
    const double r = p.VP == 1 ? dep / (dt * p.EPSO) : rate_star;
    h[kDamage] += dep / johnson_cook_fracture_strain(p, triaxiality, r, T_star);
    if (h[kDamage] >= 1) {
      if (p.EROD == 0) {
        result.failed = true;
      } else {
        h[kFailed] = 1;
        std::fill(s, s + 6, 0.0);
        pressure = std::max(pressure, 0.0);
      }
    }
  }
  if (p.PSFAIL > 0 && ep >= p.PSFAIL) result.failed = true;

  for (int i = 0; i < 6; ++i) stress[i] = s[i] - (i < 3 ? pressure : 0.0);
  result.plastic_increment = dep;
  return result;
}

}  // namespace plyimpact::material
