// OPTION 9 / *MAT_138 bilinear mixed-mode law on one point under imposed openings (seed eqs.
// 7.41-7.49, Table 8.6 values). References derived here, not taken from the library:
//  - onset on a ray (c, s) from the quadratic traction criterion (K_n c d/NFLS)^2 + (K_t s d/SFLS)^2 = 1;
//  - final opening on the ray by bisection of the mixed-mode criterion (power law or B-K) written
//    for the triangle of the bilinear law, G_I = 1/2 K_n c^2 d_0 d_F, G_II = 1/2 K_t s^2 d_0 d_F;
//  - the energies as the work of the tractions the law returns, integrated along the path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstring>
#include <numbers>
#include <random>

#include "law_paths.hpp"

namespace plyimpact::cohesive {
namespace {

using test::PathPoint;

// Round-off of the traction: (1 - d) K delta with K delta up to ~1e10 Pa and d near 1 loses
// ~1e-16 * 1e10 = 1e-6 Pa; 1e-9 of the peak traction (0.06 Pa) leaves a wide margin.
constexpr double kTractionTol = 1e-9;
// The required tolerance on energies (0.5 %), and the one the law actually meets: its dissipation
// formula is exact on a ray and the work integral is exact when the kinks (onset, final) are path
// points, so only round-off remains (1e-9 relative covers ~1e5 accumulated additions).
constexpr double kRequiredEnergyTol = 5e-3;
constexpr double kExactEnergyTol = 1e-9;

struct Ray {
  double c, s;       // direction cosines of delta_I and delta_II
  double onset, fin; // m
};

double quadratic_onset(const TractionLawParams& p, double c, double s) {
  const double kt = p.CT2CN * p.CN;
  return 1 / std::sqrt(std::pow(p.CN * c / p.NFLS, 2) + std::pow(kt * s / p.SFLS, 2));
}

// Smallest d_F at which the criterion (a function of G_I, G_II) reaches 1, by bisection.
double final_by_bisection(const TractionLawParams& p, double c, double s, double onset,
                          const std::function<double(double, double)>& criterion) {
  const double kt = p.CT2CN * p.CN;
  double lo = onset, hi = onset;
  auto f = [&](double df) { return criterion(0.5 * p.CN * c * c * onset * df, 0.5 * kt * s * s * onset * df) - 1; };
  while (f(hi) < 0) hi *= 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::function<double(double, double)> power_law(const TractionLawParams& p, double alpha) {
  return [=](double gi, double gii) { return std::pow(gi / p.ERATEN, alpha) + std::pow(gii / p.ERATES, alpha); };
}
std::function<double(double, double)> benzeggagh_kenane(const TractionLawParams& p, double eta) {
  return [=](double gi, double gii) {
    const double gt = gi + gii;
    return gt / (p.ERATEN + (p.ERATES - p.ERATEN) * std::pow(gii / gt, eta));
  };
}

// Opening along the ray (c, s) with the shear split between its two components at angle psi.
void along(const Ray& ray, double psi, double magnitude, double u[3]) {
  u[0] = ray.c * magnitude;
  u[1] = ray.s * std::cos(psi) * magnitude;
  u[2] = ray.s * std::sin(psi) * magnitude;
}

// Traction magnitude of the bilinear law on the ray (closed form of the triangle).
double envelope_magnitude(const TractionLawParams& p, const Ray& ray, double delta) {
  const double kt = p.CT2CN * p.CN;
  const double keff = std::sqrt(std::pow(p.CN * ray.c, 2) + std::pow(kt * ray.s, 2));  // |t| / delta, undamaged
  if (delta <= ray.onset) return keff * delta;
  if (delta >= ray.fin) return 0;
  return keff * ray.onset * (ray.fin - delta) / (ray.fin - ray.onset);
}

// Drives 0 -> onset -> final -> 1.2 final along the ray (kinks are path points) and checks every
// traction against the closed form; returns the path.
std::vector<PathPoint> drive_ray(const TractionLawParams& p, const Ray& ray, double psi) {
  const TractionLaw law = make_traction_law(p);
  PointHistory h;
  std::vector<PathPoint> path(1);
  traction_update(law, path[0].u, h, path[0].r);
  double a[3], b[3], c[3];
  along(ray, psi, ray.onset, a);
  along(ray, psi, ray.fin, b);
  along(ray, psi, 1.2 * ray.fin, c);
  test::drive(law, h, path[0].u, a, 200, path);
  test::drive(law, h, a, b, 4000, path);
  test::drive(law, h, b, c, 50, path);
  const double kt = p.CT2CN * p.CN;
  double last_damage = 0;
  for (const auto& pt : path) {
    const double delta = std::sqrt(std::pow(std::max(pt.u[0], 0.0), 2) + pt.u[1] * pt.u[1] + pt.u[2] * pt.u[2]);
    const double expected = envelope_magnitude(p, ray, delta);
    EXPECT_NEAR(test::norm3(pt.r.traction), expected, kTractionTol * std::max(p.NFLS, p.SFLS)) << "delta " << delta;
    // Direction: the traction is the (damaged) stiffness times the opening, component by component.
    if (pt.r.damage < 1 && delta > 0) {
      const double ratio = expected / (std::sqrt(std::pow(p.CN * ray.c, 2) + std::pow(kt * ray.s, 2)) * delta);
      EXPECT_NEAR(pt.r.traction[0], ratio * p.CN * pt.u[0], kTractionTol * p.NFLS);
      EXPECT_NEAR(pt.r.traction[1], ratio * kt * pt.u[1], kTractionTol * p.SFLS);
    }
    EXPECT_GE(pt.r.damage, last_damage);  // irreversible
    last_damage = pt.r.damage;
  }
  EXPECT_EQ(path.back().r.damage, 1.0);
  EXPECT_EQ(test::norm3(path.back().r.traction), 0.0);
  // At the onset point the quadratic criterion holds.
  const auto& at_onset = path[200];
  const double crit = std::pow(at_onset.r.traction[0] / p.NFLS, 2) +
                      (std::pow(at_onset.r.traction[1], 2) + std::pow(at_onset.r.traction[2], 2)) / (p.SFLS * p.SFLS);
  EXPECT_NEAR(crit, 1.0, 1e-12);
  return path;
}

TEST(MixedModeLaw, PureModeIFollowsTheBilinearLawAndDissipatesGIc) {
  const auto p = test::table_8_6_option9();
  const Ray ray{1, 0, p.NFLS / p.CN, 2 * p.ERATEN / p.NFLS};  // 6e-7 m, 2.55e-5 m
  const auto path = drive_ray(p, ray, 0);
  const auto w = test::work_along(path);
  EXPECT_NEAR(w.normal, p.ERATEN, kRequiredEnergyTol * p.ERATEN);
  EXPECT_NEAR(w.normal, p.ERATEN, kExactEnergyTol * p.ERATEN);
  EXPECT_NEAR(w.dissipated, p.ERATEN, kExactEnergyTol * p.ERATEN);
  EXPECT_EQ(w.shear, 0.0);
  EXPECT_EQ(path.back().r.mixity, 0.0);
}

TEST(MixedModeLaw, PureModeIIInAnyInPlaneDirectionDissipatesGIIc) {
  auto p = test::table_8_6_option9();
  p.CT2CN = 0.5;  // K_t != K_n, so the shear onset is SFLS / (CT2CN CN)
  const double kt = p.CT2CN * p.CN;
  const Ray ray{0, 1, p.SFLS / kt, 2 * p.ERATES / p.SFLS};
  for (double psi : {0.0, std::numbers::pi / 6, 2.0}) {
    const auto path = drive_ray(p, ray, psi);
    const auto w = test::work_along(path);
    EXPECT_NEAR(w.shear, p.ERATES, kRequiredEnergyTol * p.ERATES);
    EXPECT_NEAR(w.shear, p.ERATES, kExactEnergyTol * p.ERATES);
    EXPECT_NEAR(w.dissipated, p.ERATES, kExactEnergyTol * p.ERATES);
    EXPECT_NEAR(path[100].r.mixity, 1.0, 1e-15);
  }
}

// Mixed mode: power law alpha = 1 (the seed's PARAM), 2 and 1.5 (the general pow branch), and
// Benzeggagh-Kenane (negative PARAM, eta = 2). For each mixity the work per mode lies on the envelope.
TEST(MixedModeLaw, MixedModeEnergiesLieOnThePowerLawAndBkEnvelopes) {
  for (double param : {1.0, 2.0, 1.5, -2.0}) {
    auto p = test::table_8_6_option9();
    p.PARAM = param;
    p.CT2CN = 0.8;
    const auto criterion = param > 0 ? power_law(p, param) : benzeggagh_kenane(p, -param);
    for (double angle_deg : {15.0, 30.0, 45.0, 60.0, 75.0}) {
      const double th = angle_deg * std::numbers::pi / 180;  // delta_II / delta_I = tan(th)
      Ray ray{std::cos(th), std::sin(th), 0, 0};
      ray.onset = quadratic_onset(p, ray.c, ray.s);
      ray.fin = final_by_bisection(p, ray.c, ray.s, ray.onset, criterion);
      SCOPED_TRACE(testing::Message() << "PARAM " << param << ", angle " << angle_deg);
      const auto path = drive_ray(p, ray, 0.7);
      const auto w = test::work_along(path);
      const double on_envelope = criterion(w.normal, w.shear);
      EXPECT_NEAR(on_envelope, 1.0, kRequiredEnergyTol);
      EXPECT_NEAR(on_envelope, 1.0, 1e-8);  // bisection to 1e-60 relative; round-off only
      EXPECT_NEAR(w.dissipated, w.normal + w.shear, kExactEnergyTol * (w.normal + w.shear));
      // Mode mixity G_II / G_T from the openings equals the energy split.
      EXPECT_NEAR(path[100].r.mixity, w.shear / (w.normal + w.shear), 1e-12);
    }
  }
}

// Unloading and reloading follow the damaged secant; compression is the undamaged penalty and
// neither damages nor dissipates; past the old maximum the softening branch resumes.
TEST(MixedModeLaw, UnloadingAndReloadingFollowTheDamagedSecant) {
  const auto p = test::table_8_6_option9();
  const TractionLaw law = make_traction_law(p);
  const double d0 = p.NFLS / p.CN, df = 2 * p.ERATEN / p.NFLS;
  const double d1 = d0 + 0.4 * (df - d0);
  PointHistory h;
  std::vector<PathPoint> path(1);
  traction_update(law, path[0].u, h, path[0].r);
  // The kinks of the law (onset, and delta_n = 0 where the secant meets the penalty) are path
  // points, so the trapezoid work below is exact.
  const double onset[3] = {d0, 0, 0}, peak[3] = {d1, 0, 0}, zero[3] = {0, 0, 0}, compressed[3] = {-3 * d0, 0, 0};
  const double beyond[3] = {d0 + 0.6 * (df - d0), 0, 0};
  test::drive(law, h, path[0].u, onset, 100, path);
  test::drive(law, h, onset, peak, 500, path);
  const double damage = path.back().r.damage;
  const double expected_damage = df * (d1 - d0) / (d1 * (df - d0));  // eq. 7.49
  EXPECT_NEAR(damage, expected_damage, 1e-14);
  const std::size_t cycle_start = path.size();
  test::drive(law, h, peak, zero, 200, path);
  test::drive(law, h, zero, compressed, 100, path);
  test::drive(law, h, compressed, zero, 100, path);
  test::drive(law, h, zero, peak, 200, path);
  for (std::size_t i = cycle_start; i < path.size(); ++i) {
    const auto& pt = path[i];
    const double k = pt.u[0] > 0 ? (1 - damage) * p.CN : p.CN;
    EXPECT_NEAR(pt.r.traction[0], k * pt.u[0], kTractionTol * p.NFLS);
    EXPECT_EQ(pt.r.damage, damage);
    EXPECT_EQ(pt.r.dissipated_increment, 0.0);
  }
  const std::size_t resume = path.size();
  test::drive(law, h, peak, beyond, 200, path);
  for (std::size_t i = resume; i < path.size(); ++i) {
    const double u = path[i].u[0];
    EXPECT_NEAR(path[i].r.traction[0], p.NFLS * (df - u) / (df - d0), kTractionTol * p.NFLS);
  }
  // Over the whole closed cycle the work equals the dissipation: no energy made or lost.
  const auto w = test::work_along(path);
  const double stored = path.back().r.elastic_energy;
  EXPECT_NEAR(w.normal, w.dissipated + stored, kExactEnergyTol * p.ERATEN);
}

TEST(MixedModeLaw, CompressionNeverDamagesAndDoesNotInterpenetrateSoftly) {
  const auto p = test::table_8_6_option9();
  const TractionLaw law = make_traction_law(p);
  PointHistory h;
  PointResponse r;
  const double df = 2 * p.ERATEN / p.NFLS;
  const double u[3] = {-100 * df, 0, 0};
  traction_update(law, u, h, r);
  EXPECT_EQ(r.damage, 0.0);
  EXPECT_NEAR(r.traction[0], p.CN * u[0], 1e-15 * std::abs(p.CN * u[0]));
  EXPECT_NEAR(r.elastic_energy, 0.5 * p.CN * u[0] * u[0], 1e-15 * p.CN * u[0] * u[0]);
  // Shear under compression damages through the shear opening alone (delta = |delta_s|).
  const double ds = 0.5 * (p.SFLS / p.CN + 2 * p.ERATES / p.SFLS);
  const double v[3] = {-df, ds, 0};
  traction_update(law, v, h, r);
  const double s0 = p.SFLS / p.CN, sf = 2 * p.ERATES / p.SFLS;
  EXPECT_NEAR(r.damage, sf * (ds - s0) / (ds * (sf - s0)), 1e-14);
  EXPECT_NEAR(r.traction[0], p.CN * v[0], 1e-15 * std::abs(p.CN * v[0]));  // normal stays the penalty
}

// After separation: no tension, penalty in compression, Coulomb friction (stick, then slide at
// mu |t_n| dissipating mu |t_n| per unit of slip), a released stick spring when it opens again.
TEST(MixedModeLaw, SeparatedPointIsContactWithCoulombFriction) {
  auto p = test::table_8_6_option9();
  p.FS = 0.3;
  const TractionLaw law = make_traction_law(p);
  PointHistory h;
  std::vector<PathPoint> path(1);
  traction_update(law, path[0].u, h, path[0].r);
  const double df = 2 * p.ERATEN / p.NFLS;
  const double open[3] = {2 * df, 0, 0};
  test::drive(law, h, path[0].u, open, 2000, path);
  ASSERT_EQ(h.damage, 1.0);
  const double gap = -1e-6;  // closed 1 um into compression
  const double closed[3] = {gap, 0, 0};
  test::drive(law, h, open, closed, 100, path);
  const double tn = p.CN * gap;
  EXPECT_NEAR(path.back().r.traction[0], tn, 1e-12 * std::abs(tn));
  const double limit = p.FS * std::abs(tn);
  const double kt = p.CT2CN * p.CN;
  const double stick = limit / kt;       // shear opening at which sliding starts
  const double slide_to = 50 * stick;
  const double at_stick[3] = {gap, stick, 0}, slid[3] = {gap, slide_to, 0};
  const std::size_t start = path.size();
  test::drive(law, h, closed, at_stick, 20, path);  // the stick-slip kink is a path point
  test::drive(law, h, at_stick, slid, 1000, path);
  double friction = 0;
  for (std::size_t i = start; i < path.size(); ++i) {
    const auto& pt = path[i];
    const double expected = pt.u[1] <= stick ? kt * pt.u[1] : limit;
    EXPECT_NEAR(pt.r.traction[1], expected, 1e-9 * limit);
    friction += pt.r.dissipated_increment;
  }
  // Work of sliding = mu |t_n| (slip) dissipated + the stick spring's energy stored.
  EXPECT_NEAR(friction, limit * (slide_to - stick), 1e-9 * limit * slide_to);
  EXPECT_NEAR(path.back().r.elastic_energy, 0.5 * tn * gap + 0.5 * limit * limit / kt, 1e-9 * limit * slide_to);
  // Opening again: no tension, the stick spring is released into the dissipation.
  const double reopened[3] = {df, slide_to, 0};
  PathPoint last;
  std::copy(reopened, reopened + 3, last.u);
  traction_update(law, last.u, h, last.r);
  EXPECT_EQ(test::norm3(last.r.traction), 0.0);
  EXPECT_EQ(last.r.elastic_energy, 0.0);
  EXPECT_NEAR(last.r.dissipated_increment, 0.5 * limit * limit / kt, 1e-9 * limit * stick);
}


// The shortcut below every onset (TractionLaw::elastic_limit) must leave each update exactly as
// the damage growth would: random openings on random rays around the smaller single-mode onset,
// on loading paths from random histories, with the shortcut and without it (elastic_limit = 0),
// for the power law, B-K, OPTION 6 and unequal NFLS / SFLS; history and response bit-identical.
TEST(MixedModeLaw, ElasticShortcutChangesNoUpdate) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u01(0, 1), sym(-1, 1);
  int shortcut = 0;
  for (int variant = 0; variant < 4; ++variant) {
    TractionLawParams p;
    p.option = variant == 2 ? TiebreakOption::StressCcrit : TiebreakOption::MixedMode;
    p.NFLS = 60e6, p.SFLS = variant == 3 ? 90e6 : 60e6, p.CN = 1e14, p.CT2CN = variant == 3 ? 0.5 : 1;
    p.ERATEN = 765, p.ERATES = 1250;
    p.PARAM = variant == 1 ? -1.45 : variant == 2 ? 2e-5 : 1.0;
    if (p.option == TiebreakOption::StressCcrit) p.ERATEN = p.ERATES = kMissing;
    const TractionLaw with = make_traction_law(p);
    TractionLaw without = with;
    without.elastic_limit = 0;
    ASSERT_GT(with.elastic_limit, 0);
    const double scale = std::min(with.delta_n0, with.delta_s0);
    for (int path = 0; path < 400; ++path) {
      PointHistory ha, hb;
      ha.max_opening = hb.max_opening = scale * 0.5 * u01(rng);
      for (int step = 0; step < 8; ++step) {
        const double size = scale * (0.2 + 1.0 * u01(rng));  // around the smaller onset
        const double c = sym(rng), s1 = sym(rng), s2 = sym(rng);
        const double len = std::sqrt(c * c + s1 * s1 + s2 * s2);
        const double uo[3] = {size * c / len, size * s1 / len, size * s2 / len};
        const double open = std::sqrt(std::pow(std::max(uo[0], 0.0), 2) + uo[1] * uo[1] + uo[2] * uo[2]);
        if (open > ha.max_opening && open <= with.elastic_limit) ++shortcut;
        PointResponse ra, rb;
        traction_update(with, uo, ha, ra);
        traction_update(without, uo, hb, rb);
        ASSERT_EQ(std::memcmp(&ha, &hb, sizeof ha), 0) << "variant " << variant << " path " << path;
        ASSERT_EQ(std::memcmp(&ra, &rb, sizeof ra), 0) << "variant " << variant << " path " << path;
      }
    }
  }
  EXPECT_GT(shortcut, 1000);  // the shortcut was taken often enough for the comparison to count
}

}  // namespace
}  // namespace plyimpact::cohesive
