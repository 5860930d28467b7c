// Tiebreak OPTION 6 and OPTION 7 on a single point: onset, softening length, energy, friction after
// separation. Values of seed Table 8.6 (NFLS = SFLS = 60 MPa, CCRIT = 0.025 mm, ERATEN 765 and
// ERATES 1250 J/m^2, friction angle 0 there; 30 degrees here so that friction shows). CN stands for
// the penalty stiffness per area that LS-DYNA derives from the segment for these options; 1e13 Pa/m
// is a typical value for 0.25 mm plies (0.1 K / h).
// OPTION 6 as documented: stress onset, damage linear in the largest distance C, complete at
// C = CCRIT. OPTION 7's law is not documented (see docs/delamination.md); its tests pin the assumed law.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "law_paths.hpp"

namespace plyimpact::cohesive {
namespace {

constexpr double kTractionTol = 1e-9;  // of the peak traction: round-off only (see test_mixed_mode_law)
constexpr double kEnergyTol = 1e-9;    // path kinks are path points: the trapezoid work is exact

TractionLawParams option6() {
  TractionLawParams p;
  p.option = TiebreakOption::StressCcrit;
  p.NFLS = 60e6;
  p.SFLS = 60e6;
  p.PARAM = 0.025e-3;  // CCRIT
  p.CN = 1e13;
  p.FS = 0.2;
  return p;
}

TractionLawParams option7() {
  TractionLawParams p;
  p.option = TiebreakOption::DiscreteCrack;
  p.NFLS = 60e6;
  p.SFLS = 60e6;
  p.PARAM = 30;  // friction angle, degrees
  p.ERATEN = 765;
  p.ERATES = 1250;
  p.CN = 1e13;
  return p;
}

// Ray (c, s): 0 -> onset -> final -> 1.3 final, kinks as path points.
std::vector<test::PathPoint> ray_through(const TractionLaw& law, double c, double s, double onset, double fin) {
  PointHistory h;
  std::vector<test::PathPoint> path(1);
  traction_update(law, path[0].u, h, path[0].r);
  const double a[3] = {c * onset, s * onset, 0}, b[3] = {c * fin, s * fin, 0}, e[3] = {1.3 * c * fin, 1.3 * s * fin, 0};
  test::drive(law, h, path[0].u, a, 100, path);
  test::drive(law, h, a, b, 2000, path);
  test::drive(law, h, b, e, 20, path);
  return path;
}

// Traction magnitude along the ray: elastic to the onset traction t0, then linear to 0 at `fin`.
void expect_linear_softening(const std::vector<test::PathPoint>& path, double k, double onset, double fin, double t0) {
  for (const auto& pt : path) {
    const double delta = std::sqrt(std::pow(std::max(pt.u[0], 0.0), 2) + pt.u[1] * pt.u[1]);
    const double expected = delta <= onset ? k * delta : delta >= fin ? 0.0 : t0 * (fin - delta) / (fin - onset);
    EXPECT_NEAR(test::norm3(pt.r.traction), expected, kTractionTol * t0) << "delta " << delta;
  }
}

TEST(Option6, StressOnsetThenLinearSofteningToZeroAtCcrit) {
  const auto p = option6();
  const TractionLaw law = make_traction_law(p);
  const double ccrit = p.PARAM;
  // Mode I: onset where CN delta = NFLS; the traction reaches zero at C = CCRIT (the total distance).
  {
    const double onset = p.NFLS / p.CN;
    const auto path = ray_through(law, 1, 0, onset, ccrit);
    expect_linear_softening(path, p.CN, onset, ccrit, p.NFLS);
    EXPECT_NEAR(path[100].r.traction[0], p.NFLS, kTractionTol * p.NFLS);
    const auto w = test::work_along(path);
    EXPECT_NEAR(w.normal, 0.5 * p.NFLS * ccrit, kEnergyTol * p.NFLS * ccrit);  // the triangle 0 - onset - CCRIT
    EXPECT_NEAR(w.dissipated, w.normal, kEnergyTol * p.NFLS * ccrit);
    // The damage LS-DYNA reports, D = (C - C_0)/(CCRIT - C_0), is linear in C: the traction is
    // (1 - D) NFLS. Check it half way.
    const auto& mid = path[100 + 1000];
    const double c_mid = mid.u[0];
    const double d_lsdyna = (c_mid - onset) / (ccrit - onset);
    EXPECT_NEAR(mid.r.traction[0], (1 - d_lsdyna) * p.NFLS, kTractionTol * p.NFLS);
  }
  // Mode II (shear stiffness = CN) and 45 degrees: onset on the quadratic stress criterion, zero at
  // CCRIT whatever the mixity.
  for (double angle : {90.0, 45.0}) {
    const double th = angle * std::numbers::pi / 180, c = std::cos(th), s = std::sin(th);
    const double onset = 1 / std::sqrt(std::pow(p.CN * c / p.NFLS, 2) + std::pow(p.CN * s / p.SFLS, 2));
    const double t0 = p.CN * onset;
    const auto path = ray_through(law, c, s, onset, ccrit);
    expect_linear_softening(path, p.CN, onset, ccrit, t0);
    const auto w = test::work_along(path);
    EXPECT_NEAR(w.normal + w.shear, 0.5 * t0 * ccrit, kEnergyTol * t0 * ccrit);
    EXPECT_EQ(path.back().r.damage, 1.0);
  }
}

TEST(Option6, FrictionAfterFailureUsesFs) {
  const auto p = option6();
  const TractionLaw law = make_traction_law(p);
  PointHistory h;
  PointResponse r;
  const double open[3] = {2 * p.PARAM, 0, 0};
  traction_update(law, open, h, r);
  ASSERT_EQ(r.damage, 1.0);
  const double sliding[3] = {-1e-6, 1e-4, 0};  // far past the stick limit in one step
  traction_update(law, sliding, h, r);
  EXPECT_NEAR(r.traction[0], p.CN * sliding[0], 1e-12 * p.CN * 1e-6);
  EXPECT_NEAR(r.traction[1], p.FS * p.CN * 1e-6, 1e-9 * p.FS * p.CN * 1e-6);
  EXPECT_EQ(r.traction[2], 0.0);
  // No tension after failure, however small the opening.
  const double reopened[3] = {1e-12, 1e-4, 0};
  traction_update(law, reopened, h, r);
  EXPECT_EQ(test::norm3(r.traction), 0.0);
}

TEST(Option7, AssumedLawIsBilinearWithGIcAndGIIc) {
  const auto p = option7();
  const TractionLaw law = make_traction_law(p);
  {  // mode I
    const double onset = p.NFLS / p.CN, fin = 2 * p.ERATEN / p.NFLS;
    const auto path = ray_through(law, 1, 0, onset, fin);
    expect_linear_softening(path, p.CN, onset, fin, p.NFLS);
    EXPECT_NEAR(test::work_along(path).normal, p.ERATEN, kEnergyTol * p.ERATEN);
  }
  {  // mode II, shear stiffness = CN (CT2CN is not read for OPTION 7)
    const double onset = p.SFLS / p.CN, fin = 2 * p.ERATES / p.SFLS;
    const auto path = ray_through(law, 0, 1, onset, fin);
    expect_linear_softening(path, p.CN, onset, fin, p.SFLS);
    EXPECT_NEAR(test::work_along(path).shear, p.ERATES, kEnergyTol * p.ERATES);
  }
  {  // mixed (45 degrees): the assumed linear energy criterion G_I/G_Ic + G_II/G_IIc = 1
    const double c = std::sqrt(0.5), s = c;
    const double onset = 1 / std::sqrt(std::pow(p.CN * c / p.NFLS, 2) + std::pow(p.CN * s / p.SFLS, 2));
    // triangle energies G_I = 1/2 CN c^2 onset fin, G_II = 1/2 CN s^2 onset fin on the criterion:
    const double fin = 2 / (onset * (p.CN * c * c / p.ERATEN + p.CN * s * s / p.ERATES));
    const auto path = ray_through(law, c, s, onset, fin);
    expect_linear_softening(path, p.CN, onset, fin, p.CN * onset);
    const auto w = test::work_along(path);
    EXPECT_NEAR(w.normal / p.ERATEN + w.shear / p.ERATES, 1.0, 1e-9);
  }
}

TEST(Option7, FrictionAngleGivesCoulombCoefficientAfterSeparation) {
  for (double angle : {30.0, 0.0}) {
    auto p = option7();
    p.PARAM = angle;
    const TractionLaw law = make_traction_law(p);
    PointHistory h;
    PointResponse r;
    const double open[3] = {3 * p.ERATEN / p.NFLS, 0, 0};
    traction_update(law, open, h, r);
    ASSERT_EQ(r.damage, 1.0);
    const double gap = -2e-6;
    const double mu = std::tan(angle * std::numbers::pi / 180);
    const double stick = mu * std::abs(gap);  // stick spring K_t = CN: sliding starts at mu |gap|
    const double at_stick[3] = {gap, stick, 0}, sliding[3] = {gap, 5e-4, 0};
    traction_update(law, at_stick, h, r);
    EXPECT_NEAR(r.traction[1], mu * p.CN * std::abs(gap), 1e-9 * p.CN * std::abs(gap));
    traction_update(law, sliding, h, r);
    EXPECT_NEAR(r.traction[1], mu * p.CN * std::abs(gap), 1e-9 * p.CN * std::abs(gap));
    // Sliding dissipates mu |t_n| per unit slip.
    EXPECT_NEAR(r.dissipated_increment, mu * p.CN * std::abs(gap) * (5e-4 - stick), 1e-9 * p.CN * std::abs(gap) * 5e-4);
  }
}

}  // namespace
}  // namespace plyimpact::cohesive
