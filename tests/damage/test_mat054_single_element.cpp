// *MAT_054/055 single material point, driven in material axes.
// Uniaxial stress: the loaded strain component is imposed, the others are solved so that their
// stresses stay zero, so the loaded stress is E x strain with E = EA, EB or GAB exactly (compliance
// of docs/theory.md section 7). Failure points are bracketed: intact at (1 - 1e-9) of the analytic
// failure strain, failed at (1 + 1e-9). Tolerances:
//   kRel = 1e-10 on moduli and stresses: the stiffness comes from a 6x6 inverse (round-off ~1e-15
//     times a condition number ~1e2) and ~100 increments are summed (~1e-14); 1e-10 leaves margin
//     but is far below the 1e-9 bracket, so "exactly XT" is checked to 1e-9.
//   kZero = 1e-3 Pa for stresses that must vanish: the driver's lateral residual is ~1e-7 Pa.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "material/composite_damage_output.hpp"
#include "mat054_support.hpp"

namespace plyimpact::test {
namespace {

using material::CompositeDamageCause;
constexpr double kRel = 1e-10;
constexpr double kZero = 1e-3;
constexpr double kLo = 1 - 1e-9, kHi = 1 + 1e-9;
constexpr int kA = 0, kB = 1, kAB = 3;

void expect_rel(double actual, double expected, double rel = kRel) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << "expected " << expected;
}

void expect_all_zero(const PointDriver& d) {
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(d.material_stress()[i], 0.0, kZero) << "component " << i;
}

CompositeDamageCause cause(const PointDriver& d) { return static_cast<CompositeDamageCause>(d.result().cause); }

// Loads `axis` to half the failure strain (slope check), to kLo and kHi of it (failure bracket).
// Returns nothing; leaves the driver just past failure.
void load_to_failure(PointDriver& d, int axis, double modulus, double strength_signed, int flag) {
  const double eps_f = strength_signed / modulus;
  d.uniaxial_to(axis, 0.5 * eps_f, 50);
  expect_rel(d.stress()[axis] / d.strain()[axis], modulus);
  d.uniaxial_to(axis, kLo * eps_f, 50);
  EXPECT_EQ(d.flag(flag), 1.0) << "failed before the strength";
  expect_rel(d.stress()[axis], kLo * strength_signed);
  d.uniaxial_step(axis, (kHi - kLo) * eps_f);
  EXPECT_EQ(d.flag(flag), 0.0) << "not failed past the strength";
}

// ------------------------------------------------------------------ fibre direction

TEST(Mat054Fibre, TensionFailsAtXTThenErodesAtDFAILT) {
  PointDriver d(t800_card_0deg());
  const auto& m = t800_card_0deg();
  d.uniaxial_to(kA, 0.004, 40);
  // PRBA is the minor ratio: the major one, nu_ab = PRBA EA / EB, gives the lateral contraction.
  expect_rel(-d.strain()[kB] / d.strain()[kA], m.PRBA * m.EA / m.EB);
  load_to_failure(d, kA, m.EA, m.XT, H::kFibreTension);
  expect_all_zero(d);  // fibre tension removes EA, EB and GAB: nothing left in plane
  EXPECT_EQ(d.flag(H::kFibreCompression), 1.0);
  EXPECT_FALSE(d.result().erode);  // DFAILT = 1.557 % > XT/EA = 1.333 %
  d.uniaxial_to(kA, kLo * m.DFAILT, 20);
  EXPECT_FALSE(d.result().erode);
  d.uniaxial_to(kA, kHi * m.DFAILT, 1);
  EXPECT_TRUE(d.result().erode);
  EXPECT_EQ(cause(d), CompositeDamageCause::DFAILT);
}

TEST(Mat054Fibre, CompressionFailsAtXCThenErodesAtDFAILC) {
  const auto m = t800_card_0deg();
  PointDriver d(m);
  load_to_failure(d, kA, m.EA, -m.XC, H::kFibreCompression);
  EXPECT_NEAR(d.material_stress()[kA], 0.0, kZero);  // SLIMC1 blank: the stress drops to zero
  EXPECT_EQ(d.flag(H::kFibreTension), 1.0);
  EXPECT_EQ(d.flag(H::kMatrixTension), 1.0);
  EXPECT_EQ(d.flag(H::kMatrixCompression), 1.0);
  d.uniaxial_to(kA, kLo * m.DFAILC, 20);
  EXPECT_FALSE(d.result().erode);
  d.uniaxial_to(kA, kHi * m.DFAILC, 1);
  EXPECT_TRUE(d.result().erode);
  EXPECT_EQ(cause(d), CompositeDamageCause::DFAILC);
}

TEST(Mat054Fibre, SlimC1OneHoldsXCAndUnloadsElastically) {
  auto m = t800_card_0deg();
  m.SLIMC1 = 1.0;
  PointDriver d(m);
  load_to_failure(d, kA, m.EA, -m.XC, H::kFibreCompression);
  d.uniaxial_to(kA, -0.010, 20);
  expect_rel(d.stress()[kA], -m.XC);  // ideally plastic at SLIMC1 x XC
  d.uniaxial_step(kA, 0.001);
  expect_rel(d.stress()[kA], -m.XC + m.EA * 0.001);  // elastic unloading with EA
  d.uniaxial_to(kA, kHi * m.DFAILC, 20);
  EXPECT_EQ(cause(d), CompositeDamageCause::DFAILC);
  expect_all_zero(d);
}

// The Figure 7.3 card's DFAILT/DFAILC are just below XT/EA and XC/EA: strain erosion comes first.
TEST(Mat054Fibre, SeedCardErodesOnStrainBeforeTheStrength) {
  const auto m = t800_card();
  PointDriver t(m);
  t.uniaxial_to(kA, kLo * m.DFAILT, 100);
  EXPECT_FALSE(t.result().erode);
  expect_rel(t.stress()[kA], m.EA * kLo * m.DFAILT);  // 2194.5 MPa < XT = 2200 MPa
  t.uniaxial_to(kA, kHi * m.DFAILT, 1);
  EXPECT_EQ(cause(t), CompositeDamageCause::DFAILT);
  EXPECT_EQ(t.flag(H::kFibreTension), 1.0);

  PointDriver c(m);
  c.uniaxial_to(kA, kLo * m.DFAILC, 100);
  expect_rel(c.stress()[kA], m.EA * kLo * m.DFAILC);  // -1199.55 MPa, |.| < XC
  c.uniaxial_to(kA, kHi * m.DFAILC, 1);
  EXPECT_EQ(cause(c), CompositeDamageCause::DFAILC);
  EXPECT_EQ(c.flag(H::kFibreCompression), 1.0);

  PointDriver b(m);  // DFAILM = 3.66 % < YC/EB = 3.665 %
  b.uniaxial_to(kB, -kLo * m.DFAILM, 100);
  EXPECT_FALSE(b.result().erode);
  b.uniaxial_to(kB, -kHi * m.DFAILM, 1);
  EXPECT_EQ(cause(b), CompositeDamageCause::DFAILM);
  EXPECT_EQ(b.flag(H::kMatrixCompression), 1.0);
}

// ------------------------------------------------------------------ matrix direction

TEST(Mat054Matrix, TensionFailsAtYTThenErodesAtDFAILM) {
  const auto m = t800_card_0deg();
  PointDriver d(m);
  d.uniaxial_to(kB, 0.002, 20);
  expect_rel(-d.strain()[kA] / d.strain()[kB], m.PRBA);  // eps_a = -PRBA sigma_b/EB
  load_to_failure(d, kB, m.EB, m.YT, H::kMatrixTension);
  expect_all_zero(d);
  EXPECT_EQ(d.flag(H::kMatrixCompression), 1.0);
  EXPECT_EQ(d.flag(H::kFibreTension), 1.0);
  EXPECT_EQ(d.history()[H::kXC], m.XC);  // only matrix *compression* reduces XC
  d.uniaxial_to(kB, kLo * m.DFAILM, 20);
  EXPECT_FALSE(d.result().erode);
  d.uniaxial_to(kB, kHi * m.DFAILM, 1);
  EXPECT_EQ(cause(d), CompositeDamageCause::DFAILM);
}

TEST(Mat054Matrix, CompressionFailsExactlyAtYC) {
  const auto m = t800_criteria_only();
  PointDriver d(m);
  // With sigma_ab = 0, e_d = 0 at sigma_bb = -YC.
  const material::CompositeStrengths s{m.XT, m.XC, m.YT, m.YC, m.SC};
  EXPECT_NEAR(material::composite_criteria(54, m.BETA, 0, m.GAB, s, 0, -m.YC, 0).matrix_compression, 0.0, 1e-15);
  load_to_failure(d, kB, m.EB, -m.YC, H::kMatrixCompression);
  expect_all_zero(d);
  EXPECT_EQ(d.flag(H::kMatrixTension), 1.0);
  EXPECT_EQ(d.flag(H::kFibreCompression), 1.0);
  expect_rel(d.history()[H::kXC], m.YCFAC * m.YC);  // 560 MPa
  EXPECT_EQ(d.history()[H::kXT], m.XT);             // FBRT blank: no reduction
  EXPECT_FALSE(d.result().erode);
}

TEST(Mat054Matrix, SlimT2WithNcyredRampsDownThenHoldsAndUnloadsElastically) {
  auto m = t800_criteria_only();
  m.SLIMT2 = 0.2;
  m.NCYRED = 4;
  PointDriver d(m);
  load_to_failure(d, kB, m.EB, m.YT, H::kMatrixTension);
  // The ramp starts at the trial stress of the failure cycle: YT plus what the lateral strains,
  // re-solved for zero lateral stress after the drop, add through the Poisson coupling (~4 %).
  const double start = d.history()[H::kRampStart + 2], floor = 0.2 * m.YT;
  EXPECT_GT(start, m.YT);
  EXPECT_LT(start, 1.1 * m.YT);
  // Each further step loads on (the trial grows), so the limit of cycle k after the failure,
  // floor + (start - floor) max(0, 1 - k/4), is what the stress shows; from k = 4 it is the floor.
  for (int step = 0; step < 5; ++step) {
    d.uniaxial_step(kB, 0.1 * m.YT / m.EB);
    const double k = d.history()[H::kRampCycles + 2];
    expect_rel(d.stress()[kB], floor + (start - floor) * std::max(0.0, 1.0 - k / 4.0));
  }
  EXPECT_GE(d.history()[H::kRampCycles + 2], 6.0);
  d.uniaxial_step(kB, -0.05 * m.YT / m.EB);
  expect_rel(d.stress()[kB], floor - 0.05 * m.YT);  // elastic unloading with EB below the limit
}

// ------------------------------------------------------------------ in-plane shear

TEST(Mat054Shear, PureShearFailsAtSC) {
  // BMS8-212 with BETA = 0: only the matrix mode sees the shear.
  const auto m = bms8212_card();
  PointDriver d(m);
  load_to_failure(d, kAB, m.GAB, m.SC, H::kMatrixTension);  // sigma_bb = 0 counts as tension
  expect_all_zero(d);
  EXPECT_EQ(d.flag(H::kFibreTension), 1.0);
  EXPECT_EQ(d.flag(H::kMatrixCompression), 1.0);
  d.uniaxial_to(kAB, kLo * 2 * m.DFAILS, 20);  // DFAILS is tensorial: gamma_ab/2
  EXPECT_FALSE(d.result().erode);
  d.uniaxial_to(kAB, kHi * 2 * m.DFAILS, 1);
  EXPECT_EQ(cause(d), CompositeDamageCause::DFAILS);
}

TEST(Mat054Shear, BetaOneMakesPureShearAFibreTensionFailure) {
  // Figure 7.3 card (BETA = 1) without strain erosion: (0/XT)^2 + 1 (tau/SC)^2 = 1 at tau = SC,
  // so the fibre-tension mode fails with the matrix and, DFAILT being 0, erodes the point.
  const auto m = t800_criteria_only();
  PointDriver d(m);
  load_to_failure(d, kAB, m.GAB, m.SC, H::kMatrixTension);
  EXPECT_EQ(d.flag(H::kFibreTension), 0.0);
  EXPECT_TRUE(d.result().erode);
  EXPECT_EQ(cause(d), CompositeDamageCause::FibreTension);
}

TEST(Mat054Shear, AlphNonlinearShearConvergesToTheSecantLawAtFirstOrder) {
  // 2 eps_ab = tau/GAB + ALPH tau^3 (docs/theory.md section 7) integrated with the explicit tangent: the error
  // of forward Euler is O(step), so halving the step halves it (ratio 2 within 10 %).
  auto m = t800_criteria_only();
  m.ALPH = 2e-25;  // Pa^-3: doubles the strain at about 0.8 SC
  const double gamma = 0.015;
  auto exact = [&] {  // Newton on gamma = tau/G + ALPH tau^3
    double tau = 0;
    for (int i = 0; i < 60; ++i)
      tau -= (tau / m.GAB + m.ALPH * tau * tau * tau - gamma) / (1 / m.GAB + 3 * m.ALPH * tau * tau);
    return tau;
  }();
  ASSERT_LT(exact, m.SC);
  double err[2];
  for (int r = 0; r < 2; ++r) {
    PointDriver d(m);
    d.uniaxial_to(kAB, gamma, 2000 << r);
    EXPECT_EQ(d.flag(H::kMatrixTension), 1.0);
    err[r] = std::abs(d.stress()[kAB] - exact) / exact;
  }
  EXPECT_LT(err[0], 1e-3);
  EXPECT_NEAR(err[0] / err[1], 2.0, 0.2);
}

// ------------------------------------------------------------------ CRIT 54 vs 55

// Path sigma_bb = -p, sigma_ab = r p (r = 0.5), sigma_aa = sigma_cc = 0: imposed eps_bb and
// gamma_ab (eps_bb = sigma_bb/EB, gamma_ab = sigma_ab/GAB), the rest free. By hand, with
// q = YC/(2 SC):
//   CRIT 54: p^2 (1/(4 SC^2) + r^2/SC^2) - (q^2 - 1) p / YC - 1 = 0   -> p = 154.5 MPa
//   CRIT 55: p^2 (1/(YC YT) + r^2/SC^2) - (YC - YT) p / (YC YT) - 1 = 0 -> p = 143.0 MPa
double positive_root(double a, double b, double c) { return (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a); }

TEST(Mat054Crit, TsaiWuMatrixAndChangChangDifferOnCompressionPlusShear) {
  // BETA = 0: with the card's BETA = 1, sigma_aa = 0 counts as fibre tension and the shear alone
  // would fail the fibre-tension mode at tau = SC (p = 100 MPa), before either matrix envelope.
  auto base = t800_criteria_only();
  base.BETA = 0;
  const double r = 0.5, yc = base.YC, yt = base.YT, sc = base.SC, q = yc / (2 * sc);
  const double p54 = positive_root(1 / (4 * sc * sc) + r * r / (sc * sc), -(q * q - 1) / yc, -1);
  const double p55 = positive_root(1 / (yc * yt) + r * r / (sc * sc), -(yc - yt) / (yc * yt), -1);
  EXPECT_NEAR(p54, 154.5e6, 0.1e6);
  EXPECT_NEAR(p55, 143.0e6, 0.1e6);
  // Bracket 1e-7 here: two imposed and four free strains make the lateral solve exact only to
  // ~1e-9 of the stress, about the distance a 1e-9 bracket leaves to the surface.
  constexpr double kLo = 1 - 1e-7, kHi = 1 + 1e-7;
  for (int crit : {54, 55}) {
    SCOPED_TRACE(crit);
    auto m = base;
    m.CRIT = crit;
    PointDriver d(m);
    const std::array<bool, 6> fixed{false, true, false, true, false, false};
    auto go = [&](double from, double to, int n) {
      for (int k = 0; k < n; ++k) {
        const double dp = (to - from) / n;
        d.step({0, -dp / m.EB, 0, r * dp / m.GAB, 0, 0}, fixed);
      }
    };
    go(0, kLo * p55, 100);
    expect_rel(d.stress()[kB], -kLo * p55, 1e-9);
    expect_rel(d.stress()[kAB], r * kLo * p55, 1e-9);
    EXPECT_EQ(d.flag(H::kMatrixCompression), 1.0);
    go(kLo * p55, kHi * p55, 1);
    EXPECT_EQ(d.flag(H::kMatrixCompression), crit == 55 ? 0.0 : 1.0);  // below the 54 envelope
    if (crit == 54) {
      go(kHi * p55, kLo * p54, 20);
      EXPECT_EQ(d.flag(H::kMatrixCompression), 1.0);
      expect_rel(d.stress()[kB], -kLo * p54, 1e-9);
      go(kLo * p54, kHi * p54, 1);
      EXPECT_EQ(d.flag(H::kMatrixCompression), 0.0) << "e_d = " << d.history()[H::kCriteria + 3];
    }
    EXPECT_EQ(d.flag(H::kMatrixTension), 1.0);
    expect_all_zero(d);
  }
}

TEST(Mat054Crit, TsaiWuMatrixFailsAtYTAndYCUniaxially) {
  // (p - YC)(p + YT) = 0 and (p + YC)(p - YT) = 0: the CRIT 55 envelope passes through YT and -YC.
  auto m = t800_criteria_only();
  m.CRIT = 55;
  PointDriver t(m);
  load_to_failure(t, kB, m.EB, m.YT, H::kMatrixTension);
  PointDriver c(m);
  load_to_failure(c, kB, m.EB, -m.YC, H::kMatrixCompression);
}

// ------------------------------------------------------------------ FBRT and YCFAC

TEST(Mat054Strength, MatrixCompressionFailureReducesXCToYcfacYCAndXTToFbrtXT) {
  auto m = t800_criteria_only();
  m.FBRT = 0.5;
  for (int sign : {-1, +1}) {
    SCOPED_TRACE(sign);
    PointDriver d(m);
    load_to_failure(d, kB, m.EB, -m.YC, H::kMatrixCompression);
    expect_rel(d.history()[H::kXC], m.YCFAC * m.YC);  // 560 MPa
    expect_rel(d.history()[H::kXT], m.FBRT * m.XT);   // 1100 MPa
    // Now load the fibres: they fail at the reduced strength (bb is gone, so the uniaxial
    // modulus along a is still EA).
    const double strength = sign < 0 ? -m.YCFAC * m.YC : m.FBRT * m.XT;
    const int flag = sign < 0 ? H::kFibreCompression : H::kFibreTension;
    const double eps0 = d.strain()[kA];
    d.uniaxial_to(kA, eps0 + kLo * strength / m.EA, 50);
    EXPECT_EQ(d.flag(flag), 1.0);
    expect_rel(d.stress()[kA], kLo * strength, 1e-8);  // starts from sigma_aa ~ 1e-7 Pa, not 0
    d.uniaxial_step(kA, (kHi - kLo) * strength / m.EA);
    EXPECT_EQ(d.flag(flag), 0.0);
  }
}

// ------------------------------------------------------------------ erosion: EFS, TFAIL, EPSR

TEST(Mat054Erosion, EffectiveStrainEFS) {
  auto m = t800_criteria_only();
  m.EFS = 0.01;
  // Uniaxial sigma_aa: eps_bb = -nu_ab e, eps_cc = -nu_ac e (major ratios), no shear, so
  // eps_eff = e sqrt(4/3 (1 + nu_ab^2 + nu_ac^2 - nu_ab - nu_ac + nu_ab nu_ac)).
  const double nab = m.PRBA * m.EA / m.EB, nac = m.PRCA * m.EA / m.EC;
  const double e_fail = m.EFS / std::sqrt(4.0 / 3.0 * (1 + nab * nab + nac * nac - nab - nac + nab * nac));
  PointDriver d(m);
  d.uniaxial_to(kA, kLo * e_fail, 100);
  EXPECT_FALSE(d.result().erode);
  d.uniaxial_to(kA, kHi * e_fail, 1);
  EXPECT_EQ(cause(d), CompositeDamageCause::EFS);
}

TEST(Mat054Erosion, TfailAbsoluteAndRatio) {
  auto m = t800_criteria_only();
  m.TFAIL = 1e-7;  // absolute: element step below 1e-7 s
  PointDriver a(m);
  a.ctx.element_dt = 1.01e-7;
  a.uniaxial_step(kA, 1e-4);
  EXPECT_FALSE(a.result().erode);
  a.ctx.element_dt = 0.99e-7;
  a.uniaxial_step(kA, 1e-4);
  EXPECT_EQ(cause(a), CompositeDamageCause::TFAIL);
  m.TFAIL = 0.5;  // ratio dt / dt0
  PointDriver r(m);
  r.ctx.initial_dt = 2e-7;
  r.ctx.element_dt = 1.01e-7;
  r.uniaxial_step(kA, 1e-4);
  EXPECT_FALSE(r.result().erode);
  r.ctx.element_dt = 0.99e-7;
  r.uniaxial_step(kA, 1e-4);
  EXPECT_EQ(cause(r), CompositeDamageCause::TFAIL);
  expect_all_zero(r);
  r.uniaxial_step(kA, 1e-4);  // stays eroded and stress free
  EXPECT_TRUE(r.result().erode);
  expect_all_zero(r);
}

TEST(Mat054Erosion, CrashfrontSoftNeedsTfail) {
  auto m = t800_criteria_only();
  m.SOFT = 0.5;
  for (double tfail : {0.0, 1e-12}) {
    SCOPED_TRACE(tfail);
    m.TFAIL = tfail;
    PointDriver d(m);
    d.ctx.crashfront = true;
    d.ctx.element_dt = 1e-6;
    load_to_failure(d, kB, m.EB, (tfail > 0 ? m.SOFT : 1.0) * m.YT, H::kMatrixTension);
    EXPECT_EQ(d.history()[H::kCrashfront], 1.0);
  }
}

TEST(Mat054Erosion, TransverseShearDamageAndEpsrErosion) {
  auto m = t800_criteria_only();
  m.EPSF = 0.01, m.EPSR = 0.03;  // d = (gamma/2 - EPSF)/(EPSR - EPSF), capped at TSMD = 0.9
  PointDriver d(m);
  const int kBC = 4;
  d.uniaxial_to(kBC, 0.02, 20);  // gamma/2 = EPSF: no damage yet
  expect_rel(d.stress()[kBC], m.GBC * 0.02);
  d.uniaxial_to(kBC, 0.03, 10);  // gamma/2 = 0.015 -> d = 0.25, acting on the whole stress
  expect_rel(d.history()[H::kTransverseShearDamage], 0.25, 1e-9);
  expect_rel(d.stress()[kBC], 0.75 * m.GBC * 0.03, 1e-9);
  d.uniaxial_to(kBC, 0.2, 10);
  EXPECT_EQ(d.history()[H::kTransverseShearDamage], 0.9);
  d.uniaxial_to(kBC, 0.1, 10);  // unloading: d never decreases (secant unloading)
  expect_rel(d.stress()[kBC], 0.1 * m.GBC * 0.1, 1e-9);
  EXPECT_FALSE(d.result().erode);

  m.EPSR = -0.03;  // negative: erode when d reaches TSMD, at gamma/2 = 0.01 + 0.9 x 0.02 = 0.028
  PointDriver e(m);
  e.uniaxial_to(kBC, kLo * 0.056, 50);
  EXPECT_FALSE(e.result().erode);
  e.uniaxial_to(kBC, kHi * 0.056, 1);
  EXPECT_EQ(cause(e), CompositeDamageCause::TransverseShear);
}

// ------------------------------------------------------------------ helpers

TEST(Mat054Helpers, WaveModulusIsTheUndamagedOne) {
  const auto p = model::composite_damage_params(t800_card(), {"t", 0, 0, "m"});
  EXPECT_EQ(material::composite_damage_wave_modulus(p), material::max_wave_modulus(p.C));
  EXPECT_GE(p.wave_modulus, p.C[0]);  // at least the modulus along a
}

TEST(Mat054Helpers, OutputFieldsFollowTheHistory) {
  PointDriver d(t800_criteria_only());
  d.uniaxial_to(kB, 0.01, 10);  // past YT: e_m = 0
  const auto& names = material::composite_damage_output_names();
  double v[material::kCompositeDamageOutputs];
  material::composite_damage_output_values(d.history(), v);
  for (int i = 0; i < material::kCompositeDamageOutputs; ++i) {
    const std::string n = names[i];
    if (n == "mat054_em") {
      EXPECT_EQ(v[i], 0.0);
    } else if (n == "mat054_ef" || n == "mat054_ec" || n == "mat054_ed") {
      EXPECT_EQ(v[i], 1.0);
    } else if (n == "mat054_crit_matrix_tension") {
      EXPECT_GE(v[i], 0.0);
    } else if (n == "mat054_erosion_cause") {
      EXPECT_EQ(v[i], 0.0);
    }
  }
}

}  // namespace
}  // namespace plyimpact::test
