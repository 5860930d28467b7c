// *EOS_GRUNEISEN and *EOS_LINEAR_POLYNOMIAL through the *MAT_015 update, under hydrostatic
// compression and expansion (D = d I, so V = exp(3 d t) exactly as the material integrates it).
// References written here from the card formulas (LS-DYNA Keyword User's Manual Vol. II, *EOS):
//   Gruneisen, mu > 0: p = rho0 C^2 mu [1 + (1 - g0/2) mu - a/2 mu^2]
//                          / [1 - (S1 - 1) mu - S2 mu^2/(mu + 1) - S3 mu^3/(mu + 1)^2]^2 + (g0 + a mu) E,
//             mu < 0: p = rho0 C^2 mu + (g0 + a mu) E;
//   polynomial: p = C0 + C1 mu + C2 mu^2 + C3 mu^3 + (C4 + C5 mu + C6 mu^2) E, mu^2 terms off for mu < 0.
// E (energy per reference volume) follows the adiabat dE = -p dV, integrated here with RK4 in V.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "material/johnson_cook.hpp"

namespace plyimpact {
namespace {

namespace h = material::jc_history;
using material::EosParams;

constexpr double kIdentity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
constexpr double kRho0 = 8930;

// Copper on the Us-up Hugoniot (Steinberg's constants: C 3940 m/s, S1 1.489, GAMAO 2.02, A 0.47).
EosParams gruneisen(double gamma, double a) {
  EosParams q;
  q.kind = EosParams::Kind::Gruneisen;
  q.C = 3940, q.S1 = 1.489, q.S2 = 0.3, q.S3 = -0.2, q.GAMAO = gamma, q.A = a, q.rho0 = kRho0;
  return q;
}

EosParams polynomial() {
  EosParams q;
  q.kind = EosParams::Kind::LinearPolynomial;
  q.C0 = 1e6, q.C1 = 140e9, q.C2 = 250e9, q.C3 = 100e9, q.C4 = 1.9, q.C5 = 0.5, q.C6 = 0.3;
  return q;
}

double gruneisen_reference(const EosParams& q, double mu, double E) {
  const double k = q.rho0 * q.C * q.C;
  if (mu < 0) return k * mu + (q.GAMAO + q.A * mu) * E;
  const double den = 1 - (q.S1 - 1) * mu - q.S2 * mu * mu / (mu + 1) - q.S3 * std::pow(mu, 3) / std::pow(mu + 1, 2);
  return k * mu * (1 + (1 - q.GAMAO / 2) * mu - q.A / 2 * mu * mu) / (den * den) + (q.GAMAO + q.A * mu) * E;
}

double polynomial_reference(const EosParams& q, double mu, double E) {
  const double m2 = mu < 0 ? 0.0 : mu * mu;
  return q.C0 + q.C1 * mu + q.C2 * m2 + q.C3 * mu * mu * mu + (q.C4 + q.C5 * mu + q.C6 * m2) * E;
}

// Drives a material point from V = 1 to V_end in n equal steps of ln V; returns the pressure.
double compress(const EosParams& eos, double V_end, int n, double history[material::kJohnsonCookHistory]) {
  material::JohnsonCookParams p;
  p.rho0 = kRho0, p.shear = 46e9, p.A = 1e12;  // no yield under a hydrostatic path anyway
  p.eos = eos;
  const double dt = 1e-9, d = std::log(V_end) / (3 * n * dt);
  const double D[6] = {d, d, d, 0, 0, 0};
  double s[6] = {};
  // The solver's initial evaluation (dt = 0) sets the pressure of the state at rest, p(0, E0).
  material::johnson_cook_update(p, kIdentity, D, 0.0, s, history);
  for (int i = 0; i < n; ++i) material::johnson_cook_update(p, kIdentity, D, dt, s, history);
  EXPECT_EQ(s[3], 0.0);
  return -(s[0] + s[1] + s[2]) / 3;
}

// E at V_end on the adiabat dE/dV = -p(mu(V), E) from E(1) = E0, RK4 with 20000 steps.
double adiabat_energy(const std::function<double(double, double)>& pressure, double E0, double V_end) {
  const int n = 20000;
  const double hV = (V_end - 1) / n;
  double E = E0, V = 1;
  auto f = [&](double v, double e) { return -pressure(1 / v - 1, e); };
  for (int i = 0; i < n; ++i) {
    const double k1 = f(V, E), k2 = f(V + hV / 2, E + hV / 2 * k1), k3 = f(V + hV / 2, E + hV / 2 * k2),
                 k4 = f(V + hV, E + hV * k3);
    E += hV / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    V += hV;
  }
  return E;
}

class Compression : public ::testing::TestWithParam<double> {};  // relative volume V at the end

TEST_P(Compression, GruneisenColdCurveMatchesTheFormula) {
  // GAMAO = A = 0: p depends on mu only, so it must match the formula to round-off.
  const EosParams q = gruneisen(0, 0);
  double hist[material::kJohnsonCookHistory] = {};
  const double p = compress(q, GetParam(), 200, hist);
  const double mu = 1 / std::exp(hist[h::kLogVolume]) - 1;
  EXPECT_NEAR(mu, 1 / GetParam() - 1, 1e-12);
  EXPECT_NEAR(p, gruneisen_reference(q, mu, 0), 1e-12 * std::abs(p));
}

TEST_P(Compression, GruneisenWithEnergyFollowsTheAdiabat) {
  EosParams q = gruneisen(2.02, 0.47);
  q.E0 = 2e8;
  double hist[material::kJohnsonCookHistory] = {};
  const double p = compress(q, GetParam(), 4000, hist);
  const double mu = 1 / GetParam() - 1;
  const double E = adiabat_energy([&](double m, double e) { return gruneisen_reference(q, m, e); }, q.E0, GetParam());
  // The material closes each step with the trapezoid rule on p dV (second order; steps of dV ~ 5e-5):
  // 1e-6 of the energy and the pressure bound it. The energy term is a large share of p: GAMAO E0 = 0.4 GPa.
  EXPECT_NEAR(hist[h::kEnergy] + q.E0, E, 1e-6 * std::abs(E));
  EXPECT_NEAR(p, gruneisen_reference(q, mu, E), 1e-6 * std::abs(p) + 1.0);
}

TEST_P(Compression, LinearPolynomialFollowsTheAdiabat) {
  EosParams q = polynomial();
  q.E0 = 1e8;
  double hist[material::kJohnsonCookHistory] = {};
  const double p = compress(q, GetParam(), 4000, hist);
  const double mu = 1 / GetParam() - 1;
  const double E = adiabat_energy([&](double m, double e) { return polynomial_reference(q, m, e); }, q.E0, GetParam());
  EXPECT_NEAR(hist[h::kEnergy] + q.E0, E, 1e-6 * std::abs(E));
  EXPECT_NEAR(p, polynomial_reference(q, mu, E), 1e-6 * std::abs(p) + 1.0);
}

// Compressions mu = 0.02, 0.1, 0.25 and an expansion mu = -0.04.
INSTANTIATE_TEST_SUITE_P(Eos, Compression, ::testing::Values(1 / 1.02, 1 / 1.1, 1 / 1.25, 1 / 0.96));

TEST(Eos, ReferenceBulkModulusIsTheSlopeAtRest) {
  // dp/dmu at mu = 0 by central difference (mu^2 and mu^3 terms: O(h^2)).
  for (const EosParams& q : {gruneisen(2.02, 0.47), polynomial()}) {
    const double hmu = 1e-6;
    const double slope = (material::eos_pressure(q, hmu, 0) - material::eos_pressure(q, -hmu, 0)) / (2 * hmu);
    EXPECT_NEAR(material::eos_reference_bulk_modulus(q), slope, 1e-3 * slope);
  }
}

}  // namespace
}  // namespace plyimpact
