// *MAT_003 / *MAT_024 at a material point under uniaxial stress (lateral strain rates solved so the
// lateral stresses vanish). References: linear hardening sigma = SIGY + ETAN (eps - SIGY/E);
// reverse yield after a stress range of 2 SIGY (kinematic, BETA = 0) or at -sigma_max (isotropic,
// BETA = 1); Cowper-Symonds yield scaling 1 + (rate/C)^(1/P); MAT_024
// stress equal to the hardening curve at the current plastic strain (exact segment-wise return).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "material/plasticity.hpp"

namespace plyimpact {
namespace {

using material::PlasticityParams;

constexpr double kIdentity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

struct Point {
  double stress[6] = {};
  double history[material::kPlasticityHistory] = {};
};

// One uniaxial-stress increment along x at strain rate `rate` over dt: the lateral rate d (same in
// y and z) is found by secant iterations on sigma_yy = 0 (the response is piecewise linear in d).
material::PlasticityResult uniaxial_step(const PlasticityParams& p, Point& pt, double rate, double dt, double* D_used = nullptr) {
  auto trial = [&](double d, Point& out) {
    out = pt;
    const double D[6] = {rate, d, d, 0, 0, 0};
    return material::plasticity_update(p, kIdentity, D, dt, out.stress, out.history);
  };
  double d0 = -p.nu * rate, d1 = -0.5 * rate;
  Point a, b;
  trial(d0, a);
  trial(d1, b);
  for (int it = 0; it < 30 && std::abs(b.stress[1]) > 1e-9 * (std::abs(b.stress[0]) + 1.0); ++it) {
    const double d2 = d1 - b.stress[1] * (d1 - d0) / (b.stress[1] - a.stress[1]);
    d0 = d1, a = b, d1 = d2;
    trial(d1, b);
  }
  const auto r = trial(d1, pt);
  if (D_used) {
    const double D[6] = {rate, d1, d1, 0, 0, 0};
    std::copy(D, D + 6, D_used);
  }
  return r;
}

constexpr double E = 200e9, PR = 0.3, SIGY = 250e6, ETAN = 2e9;

class LinearHardening : public ::testing::TestWithParam<double> {};

TEST_P(LinearHardening, FollowsBilinearCurve) {
  const PlasticityParams p = material::plastic_kinematic(E, PR, SIGY, ETAN, GetParam(), 0, 0, 0);
  Point pt;
  const double rate = 1.0, dt = 1e-6;  // strain increments of 1e-6
  double eps = 0;
  for (int n = 0; n < 10000; ++n) {
    uniaxial_step(p, pt, rate, dt);
    eps += rate * dt;
    const double expected = eps <= SIGY / E ? E * eps : SIGY + ETAN * (eps - SIGY / E);
    // The return is exact for linear hardening; the residual error is the lateral-stress solve
    // (1e-9 relative) and the one increment that straddles the yield point (E - ETAN) * 1e-6.
    ASSERT_NEAR(pt.stress[0], expected, (E - ETAN) * rate * dt + 1e-6 * expected) << "eps = " << eps;
  }
  EXPECT_NEAR(pt.stress[0], 267.5e6, 0.2e6);
  EXPECT_NEAR(pt.history[0], 0.01 - 267.5e6 / E, 1e-6);  // plastic strain = total - elastic
}

INSTANTIATE_TEST_SUITE_P(Mat003, LinearHardening, ::testing::Values(0.0, 0.5, 1.0));

// Load to eps = 1 %, reverse, and find the stress at which plastic flow resumes.
double reverse_yield_stress(double beta) {
  const PlasticityParams p = material::plastic_kinematic(E, PR, SIGY, ETAN, beta, 0, 0, 0);
  Point pt;
  const double dt = 1e-6;
  for (int n = 0; n < 10000; ++n) uniaxial_step(p, pt, 1.0, dt);
  for (int n = 0; n < 40000; ++n) {
    const double before = pt.stress[0];
    const auto r = uniaxial_step(p, pt, -1.0, dt);
    if (r.plastic_increment > 0) return before;  // last elastic stress before flow resumed
  }
  return 0;
}

TEST(Mat003, BauschingerKinematicVersusIsotropic) {
  const double sigma_max = SIGY + ETAN * (0.01 - SIGY / E);
  const double tol = E * 1e-6;  // one strain increment of stress
  EXPECT_NEAR(reverse_yield_stress(0.0), sigma_max - 2 * SIGY, tol);  // kinematic: range 2 SIGY
  EXPECT_NEAR(reverse_yield_stress(1.0), -sigma_max, tol);            // isotropic: -sigma_max
}

TEST(Mat003, CowperSymondsScalesTheYieldStress) {
  // Fixed strain rate D = (rate, -PR rate, -PR rate): uniaxial stress while elastic, and a constant
  // rate measure sqrt(D:D) (solving the lateral rate would couple it to the yield point).
  const double C = 40.4, P = 5.0, rate = 100.0, dt = 1e-9;  // strain increments of 1e-7
  const PlasticityParams p = material::plastic_kinematic(E, PR, SIGY, 0.0, 0.0, C, P, 0);
  const double D[6] = {rate, -PR * rate, -PR * rate, 0, 0, 0};
  Point pt;
  double first_yield = 0;
  for (int n = 0; n < 40000 && first_yield == 0; ++n) {
    const double before = pt.stress[0];
    if (material::plasticity_update(p, kIdentity, D, dt, pt.stress, pt.history).plastic_increment > 0)
      first_yield = before;
  }
  const double expected = SIGY * (1 + std::pow(rate * std::sqrt(1 + 2 * PR * PR) / C, 1 / P));
  // Flow starts inside the step after the last elastic one: tolerance one increment, E rate dt.
  EXPECT_LE(first_yield, expected);
  EXPECT_GT(first_yield, expected - E * rate * dt);
  EXPECT_GT(expected, 2.0 * SIGY);  // the effect is large at 100/s: the test discriminates
}

// Uniaxial stress along the curve, by hand from the total strain eps: on the segment k of the curve
// (e_k, s_k) .. (e_k+1, s_k+1), slope H, the stress is s = s_k + H (ep - e_k) with the plastic
// strain ep = eps - s / E, so s = (s_k + H (eps - e_k)) / (1 + H / E) (valid while ep stays on the
// segment). Tolerance: the lateral-stress solve (1e-6 relative), and in the one increment that
// straddles the yield point or a kink of the curve, one elastic increment E * 1e-5.
// Returns the stress and the branch (0 elastic, k + 1 on segment k).
std::pair<double, int> mat024_uniaxial(double eps, const std::vector<double>& e, const std::vector<double>& s) {
  if (eps * E <= s[0]) return {E * eps, 0};
  for (std::size_t k = 0; k + 1 < e.size(); ++k) {
    const double H = (s[k + 1] - s[k]) / (e[k + 1] - e[k]);
    const double sigma = (s[k] + H * (eps - e[k])) / (1 + H / E);
    if (eps - sigma / E <= e[k + 1]) return {sigma, int(k) + 1};
  }
  return {0, -1};  // beyond the curve: not reached here (FAIL = 0.15 < 0.2)
}

TEST(Mat024, StressFollowsTheHardeningCurve) {
  const std::vector<double> eps = {0.0, 0.05, 0.2}, sig = {300e6, 400e6, 450e6};
  const PlasticityParams p = material::piecewise_linear(E, PR, 0, 0, 0, 0, 0.15, eps, sig);
  Point pt;
  bool failed = false;
  double total = 0;
  int branch = 0;
  for (int n = 0; n < 20000 && !failed; ++n) {
    const auto r = uniaxial_step(p, pt, 1.0, 1e-5);
    total += 1e-5;
    const auto [want, now] = mat024_uniaxial(total, eps, sig);
    const double straddle = now != branch ? E * 1e-5 : 0.0;  // the increment crossing a kink
    branch = now;
    ASSERT_NEAR(pt.stress[0], want, 1e-6 * want + straddle) << "eps = " << total;
    if (r.plastic_increment > 0) {
      ASSERT_NEAR(pt.history[0], total - want / E, 1e-6 * total + 1e-5) << "eps = " << total;
    }
    failed = r.failed;
  }
  EXPECT_TRUE(failed);                                // FAIL = 0.15 reached
  EXPECT_NEAR(pt.history[0], 0.15, 1e-3);             // within one step of plastic strain
  EXPECT_NEAR(material::yield_stress(p, 0.125), 0.5 * (400e6 + 450e6), 1);
}

TEST(Plasticity, StateRotatesObjectively) {
  const PlasticityParams p = material::plastic_kinematic(E, PR, SIGY, ETAN, 0.0, 0, 0, 0);
  Point pt;
  for (int n = 0; n < 3000; ++n) uniaxial_step(p, pt, 1.0, 1e-6);
  const Point before = pt;
  const double Rz[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};  // 90 degrees about z
  const double zero[6] = {};
  material::plasticity_update(p, Rz, zero, 0.0, pt.stress, pt.history);
  EXPECT_NEAR(pt.stress[1], before.stress[0], 1e-9 * before.stress[0]);
  EXPECT_NEAR(pt.stress[0], before.stress[1], 1e-9 * before.stress[0]);
  EXPECT_NEAR(pt.history[2], before.history[1], 1e-9 * std::abs(before.history[1]));  // back stress yy <- xx
  EXPECT_EQ(pt.history[0], before.history[0]);  // no plastic flow from a rotation
}

}  // namespace
}  // namespace plyimpact
