// *MAT_015 / *MAT_098 at a material point, against answers worked out here by hand.
// Isochoric paths (tr D = 0) keep the pressure at 0 and the deviator on one direction, so the
// radial return has the closed form sigma_bar = sigma_y(ep) with ep = eps_eq - sigma_bar / (3 G)
// (eps_eq: the equivalent total strain, rate * t): the update must meet it to the iteration
// tolerance. Paths: uniaxial (D = r (1, -1/2, -1/2)) and simple shear (D_xy = g/2, eps_eq = g t/sqrt 3).
// Heating: dT = TQC sigma_y dep / (rho CP), integrated here with RK4 in ep; the material takes T at
// the start of each step (explicit), an O(dep) lag bounded below. Energy: the stress work
// int sigma:D dt equals the stored elastic energy sigma_bar^2 / (6 G) plus the plastic work, which
// the material books with the trapezoid rule, like the element books the stress work.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>

#include "material/johnson_cook.hpp"

namespace plyimpact {
namespace {

using material::JohnsonCookParams;
namespace h = material::jc_history;

constexpr double kIdentity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

// OFHC copper (Johnson & Cook 1983, Table 1): A 90 MPa, B 292 MPa, N 0.31, C 0.025, M 1.09,
// TM 1356 K; G 46 GPa, rho 8960 kg/m^3, CP 383 J/(kg K).
JohnsonCookParams copper(bool heating) {
  JohnsonCookParams p;
  p.rho0 = 8960, p.shear = 46e9, p.bulk = 137e9;
  p.A = 90e6, p.B = 292e6, p.N = 0.31, p.C = 0.025, p.M = 1.09, p.TM = 1356, p.TR = 293, p.EPSO = 1;
  p.CP = heating ? 383 : 0;
  return p;
}

struct Point {
  double stress[6] = {};
  double history[material::kJohnsonCookHistory] = {};
  double work = 0;  // int sigma:D dt (trapezoid), J/m^3
};

void step(const JohnsonCookParams& p, Point& pt, const double D[6], double dt) {
  double old[6];
  std::copy(pt.stress, pt.stress + 6, old);
  material::johnson_cook_update(p, kIdentity, D, dt, pt.stress, pt.history);
  for (int i = 0; i < 6; ++i) pt.work += 0.5 * (old[i] + pt.stress[i]) * D[i] * dt * (i < 3 ? 1.0 : 2.0);
}

double effective_stress(const double s[6]) {
  const double m = (s[0] + s[1] + s[2]) / 3;
  const double a = s[0] - m, b = s[1] - m, c = s[2] - m;
  return std::sqrt(1.5 * (a * a + b * b + c * c + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
}

// The closed form: sigma_bar solving sigma_bar = f(eps_eq - sigma_bar / 3G) (f increasing), by bisection.
double closed_form(const std::function<double(double)>& f, double eps_eq, double G) {
  if (3 * G * eps_eq <= f(0)) return 3 * G * eps_eq;
  double lo = f(0), hi = 3 * G * eps_eq;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid - f(eps_eq - mid / (3 * G)) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Path {
  const char* name;
  double D[6];
  double eq_rate;  // equivalent total strain rate sqrt(2/3 D':D')
};

Path uniaxial(double r) { return {"uniaxial", {r, -0.5 * r, -0.5 * r, 0, 0, 0}, r}; }
Path shear(double g) { return {"shear", {0, 0, 0, 0.5 * g, 0, 0}, g / std::sqrt(3.0)}; }

class FlowStress : public ::testing::TestWithParam<double> {};

// Constant rate, no heating: sigma_bar = (A + B ep^N)(1 + C ln rate*) along the whole path.
TEST_P(FlowStress, IsochoricPathsFollowTheClosedForm) {
  const double rate = GetParam();
  const JohnsonCookParams p = copper(false);
  const double factor = 1 + p.C * std::log(std::max(rate / p.EPSO, 1.0));
  auto f = [&](double ep) { return (p.A + p.B * std::pow(std::max(ep, 0.0), p.N)) * factor; };
  for (const Path& path : {uniaxial(rate), shear(rate * std::sqrt(3.0))}) {
    Point pt;
    const double dt = 2e-4 / rate;  // equivalent strain increments of 2e-4, to 0.5
    for (int n = 1; n <= 2500; ++n) {
      step(p, pt, path.D, dt);
      const double want = closed_form(f, path.eq_rate * dt * n, p.shear);
      // The return is exact on a proportional path; 1e-9: the Newton tolerance (1e-12) and the
      // finite-difference slope only steer it.
      ASSERT_NEAR(effective_stress(pt.stress), want, 1e-9 * want) << path.name << " step " << n;
    }
    EXPECT_NEAR(pt.history[h::kPlasticStrain], 0.5 - effective_stress(pt.stress) / (3 * p.shear), 1e-9);
    EXPECT_NEAR(pt.stress[0] + pt.stress[1] + pt.stress[2], 0.0, 1e-12 * p.A);  // no pressure on an isochoric path
    // Energy: stress work = elastic energy + plastic work. On a proportional path the trapezoid stress
    // work of a step minus the change of sigma_bar^2 / 6G is exactly (sigma_n + sigma_n+1)/2 dep, the
    // material's plastic work: round-off only (1e-12).
    const double sbar = effective_stress(pt.stress);
    EXPECT_NEAR(pt.work, sbar * sbar / (6 * p.shear) + pt.history[h::kPlasticWork], 1e-12 * pt.work) << path.name;
  }
}

// 1/s (no rate effect), 1e3/s (+17 %), 1e5/s (+29 %).
INSTANTIATE_TEST_SUITE_P(Mat015, FlowStress, ::testing::Values(1.0, 1e3, 1e5));

TEST(Mat015, AdiabaticHeatingSoftensAsIntegratedByHand) {
  JohnsonCookParams p = copper(true);
  p.TQC = 0.9;
  const double rate = 1e3, dt = 1e-8;  // equivalent strain increments of 1e-5, to 1.0
  const double factor = 1 + p.C * std::log(rate);
  auto sigma_y = [&](double ep, double dT) {
    const double Ts = dT / (p.TM - p.TR);
    return (p.A + p.B * std::pow(std::max(ep, 0.0), p.N)) * factor * (1 - std::pow(Ts, p.M));
  };
  const Path path = uniaxial(rate);
  Point pt;
  for (int n = 0; n < 100000; ++n) step(p, pt, path.D, dt);
  // Reference: dT/dep = TQC sigma_y(ep, T) / (rho CP), RK4 in ep from 0 to the material's ep.
  const double ep_end = pt.history[h::kPlasticStrain];
  double dT = 0;
  const int steps = 20000;
  const double hep = ep_end / steps;
  auto slope = [&](double ep, double T) { return p.TQC * sigma_y(ep, T) / (p.rho0 * p.CP); };
  for (int i = 0; i < steps; ++i) {
    const double e = i * hep;
    const double k1 = slope(e, dT), k2 = slope(e + hep / 2, dT + hep / 2 * k1), k3 = slope(e + hep / 2, dT + hep / 2 * k2),
                 k4 = slope(e + hep, dT + hep * k3);
    dT += hep / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  std::cout << "adiabatic copper at 1e3/s to ep = " << ep_end << ": dT " << pt.history[h::kTemperatureRise]
            << " K (by hand " << dT << " K), flow stress " << effective_stress(pt.stress) / 1e6 << " MPa (by hand "
            << sigma_y(ep_end, dT) / 1e6 << ", isothermal " << sigma_y(ep_end, 0) / 1e6 << ")\n";
  // The material lags T by one increment (dep = 1e-5 of ~1): relative error ~1e-5; 1e-4 bounds it.
  EXPECT_NEAR(pt.history[h::kTemperatureRise], dT, 1e-4 * dT);
  EXPECT_NEAR(effective_stress(pt.stress), sigma_y(ep_end, dT), 1e-4 * sigma_y(ep_end, dT));
  EXPECT_LT(sigma_y(ep_end, dT), 0.95 * sigma_y(ep_end, 0));  // the heating matters: the test discriminates
  // Heat = TQC x plastic work (both per reference volume; V = 1 on this path).
  EXPECT_NEAR(p.rho0 * p.CP * pt.history[h::kTemperatureRise], p.TQC * pt.history[h::kPlasticWork],
              1e-12 * pt.history[h::kPlasticWork]);
}

TEST(Mat015, ViscoplasticRateFromThePlasticStrainRate) {
  // VP 1: once the flow is steady the plastic rate equals the total one, so the stress meets the
  // VP 0 closed form at the same rate; the first plastic steps (plastic rate below the total) lie
  // below it.
  JohnsonCookParams p = copper(false);
  p.VP = 1;
  const double rate = 1e3, dt = 2e-7;
  const double factor = 1 + p.C * std::log(rate);
  auto f = [&](double ep) { return (p.A + p.B * std::pow(std::max(ep, 0.0), p.N)) * factor; };
  const Path path = uniaxial(rate);
  Point pt;
  for (int n = 1; n <= 2500; ++n) step(p, pt, path.D, dt);
  const double want = closed_form(f, 0.5, p.shear);
  // Steady flow: dep/dt differs from the total rate by the elastic rate (d sigma / dt)/(3G), a
  // fraction ~ B N ep^(N-1) / (3G) ~ 1e-3 at ep = 0.5: the log term moves by C x 1e-3.
  EXPECT_NEAR(effective_stress(pt.stress), want, 1e-4 * want);
}

TEST(Mat015, JohnsonCookDamageErodesAtTheFractureStrain) {
  // Isochoric: sigma* = 0, so eps_f = (D1 + D2)(1 + D4 ln rate*) at T* = 0. Copper (Johnson & Cook
  // 1985): D1 0.54, D2 4.89, D3 -3.03, D4 0.014, D5 1.12 -> eps_f = 5.43 (1 + 0.014 ln 1000) = 5.955.
  JohnsonCookParams p = copper(false);
  p.D1 = 0.54, p.D2 = 4.89, p.D3 = -3.03, p.D4 = 0.014, p.D5 = 1.12;
  const double rate = 1e3, dt = 1e-6;  // increments of 1e-3
  const double eps_f = (p.D1 + p.D2) * (1 + p.D4 * std::log(rate));
  const Path path = uniaxial(rate);
  Point pt;
  bool failed = false;
  for (int n = 0; n < 10000 && !failed; ++n)
    failed = material::johnson_cook_update(p, kIdentity, path.D, dt, pt.stress, pt.history).failed;
  ASSERT_TRUE(failed);
  EXPECT_NEAR(pt.history[h::kPlasticStrain], eps_f, 1e-3 + 1e-9);  // within the increment that crossed it
  EXPECT_NEAR(pt.history[h::kDamage], 1.0, 1e-3 / eps_f + 1e-9);
  // EROD 1: the point keeps only compressive pressure instead of eroding.
  p.EROD = 1;
  Point keep;
  for (int n = 0; n < 10000; ++n) ASSERT_FALSE(material::johnson_cook_update(p, kIdentity, path.D, dt, keep.stress, keep.history).failed);
  EXPECT_EQ(keep.history[h::kFailed], 1.0);
  EXPECT_EQ(effective_stress(keep.stress), 0.0);
}

TEST(Mat098, SaturationCapsAndFailureStrain) {
  // *MAT_098: SIGMAX caps A + B ep^N before the rate term, SIGSAT the result after it, PSFAIL erodes.
  JohnsonCookParams p = copper(false);
  p.simplified = true;
  p.SIGMAX = 250e6, p.SIGSAT = 280e6, p.PSFAIL = 0.8;
  const double rate = 1e5, dt = 1e-8;  // increments of 1e-3
  const double factor = 1 + p.C * std::log(rate);  // 1.288: 250 MPa -> 322 MPa, above SIGSAT
  const Path path = uniaxial(rate);
  Point pt;
  bool failed = false;
  double at_half = 0;
  for (int n = 1; n <= 2000 && !failed; ++n) {
    failed = material::johnson_cook_update(p, kIdentity, path.D, dt, pt.stress, pt.history).failed;
    if (n == 500) at_half = effective_stress(pt.stress);
  }
  // At eps_eq = 0.5: A + B ep^N = 90 + 292 x 0.5^0.31 = 327 MPa > SIGMAX, so sigma_bar = min(250 x 1.288, 280).
  EXPECT_NEAR(at_half, 280e6, 1e-9 * 280e6);
  EXPECT_GT(250e6 * factor, 280e6);
  EXPECT_TRUE(failed);
  EXPECT_NEAR(pt.history[h::kPlasticStrain], 0.8, 1e-3 + 1e-9);
  EXPECT_EQ(pt.history[h::kTemperatureRise], 0.0);  // no heating in the simplified model
  // Below SIGMAX and SIGSAT the flow stress is the plain Johnson-Cook one.
  EXPECT_NEAR(material::johnson_cook_flow_stress(p, 0.01, 1e3, 0), (90e6 + 292e6 * std::pow(0.01, 0.31)) * (1 + 0.025 * std::log(1e3)),
              1e-6);
}

}  // namespace
}  // namespace plyimpact
