// Hourglass control on a single element: a pure hourglass velocity mode Gamma_1 (x-direction) is
// resisted under every IHQ, with exactly the force of the formulation (cube of side h, so gamma =
// Gamma and the hourglass rate is g = sum_k v_k Gamma_k = 8 v0):
//   viscous IHQ 1-3:   f_k = -a_h g Gamma_k,          a_h = QM rho V^(2/3) c / 4   (at t = 0)
//   stiffness IHQ 4-5: f_k = -k_h g dt Gamma_k,       k_h = QM rho c^2 V sum(b^2) / 4, sum(b^2) = 3/(2h^2)
//   assumed strain IHQ 6: f_k = -k_h g dt Gamma_k,    k_h = QM E V / (24 (h/2)^2) / 8
// and rigid translation and rotation are not resisted (no hourglass energy) on a skewed element
// for IHQ 2-5. Tolerances: 1e-12 relative (a few dozen floating-point operations).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "element/hex8.hpp"
#include "hourglass/assumed_strain.hpp"
#include "material/composite_damage.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

std::string cube_yaml(int ihq) {
  return "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n  m: {card: MAT_001, RO: 7800, E: 200e9, PR: 0.3}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: " + std::to_string(ihq) + ", QM: 0.1, Q1: 0, Q2: 0}\n"
         "parts:\n  p: {material: m, section: s}\nmesh:\n  boxes:\n    - {part: p, size: [0.01, 0.01, 0.01], elements: [1, 1, 1]}\n";
}

class HourglassMode : public ::testing::TestWithParam<int> {};

TEST_P(HourglassMode, PureModeIsResistedWithTheFormulationForce) {
  const int ihq = GetParam();
  model::Model model = test::model_from_yaml(cube_yaml(ihq));
  const double h = 0.01, v0 = 1.0, V = h * h * h;
  const Index* conn = model.blocks[0].conn.data();  // local element node k -> global node
  for (int k = 0; k < 8; ++k) model.v0[3 * std::size_t(conn[k])] = v0 * element::kGamma[0][k];
  const double rho = 7800, E = 200e9, nu = 0.3;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)), c = std::sqrt(M / rho), qm = 0.1;
  solver::Solver s(model);
  if (ihq <= 3) {
    const double ah = qm * rho * std::cbrt(V * V) * c / 4;
    for (int k = 0; k < 8; ++k)
      EXPECT_NEAR(s.state().f[3 * std::size_t(conn[k])], -ah * 8 * v0 * element::kGamma[0][k], 1e-12 * ah * 8 * v0);
  } else {
    const double dt = 1e-8;
    s.state().dt_next_half = dt;
    s.step();
    // Mode velocity at t^{1/2} is still v0 Gamma (no force at t = 0 for the stiffness form). The
    // stiffness is evaluated on the geometry at t^1, which the mode has moved by dt v0 / h = 1e-6
    // relative: tolerance 1e-5 relative.
    // IHQ 6: the x-displacement mode xi eta carries eps_xx = q eta / a (a = h/2, amplitude rate
    // q' = g/8 = v0) with the uniaxial modulus E: dQ = QM V E q' dt / (24 a^2) (see the IHQ 6 test
    // below), i.e. an equivalent k_h = QM V E / (24 a^2) / 8 per unit g dt.
    const double kh = ihq == 6 ? qm * V * E / (24 * (h / 2) * (h / 2)) / 8 : qm * rho * c * c * V * (1.5 / (h * h)) / 4;
    for (int k = 0; k < 8; ++k)
      EXPECT_NEAR(s.state().f[3 * std::size_t(conn[k])], -kh * 8 * v0 * dt * element::kGamma[0][k],
                  1e-5 * kh * 8 * v0 * dt);
  }
}

TEST_P(HourglassMode, RigidMotionIsNotResistedOnSkewedElement) {
  const int ihq = GetParam();
  const config::Scene scene = config::load_scene_from_string(cube_yaml(ihq), "cube.yaml");
  mesh::Mesh mesh = mesh::mesh_boxes(scene);
  // Skew the element: shift the top face and warp one corner.
  for (int k = 4; k < 8; ++k) mesh.coords[3 * k] += 0.003;
  mesh.coords[3 * 6 + 2] += 0.002;  // warp one corner out of its face and sideways
  mesh.coords[3 * 6 + 1] += 0.002;
  model::Model model = model::build_model(scene, mesh);
  const double omega = 1000.0;  // rad/s about z through the origin, plus a translation
  for (std::size_t n = 0; n < model.num_nodes(); ++n) {
    model.v0[3 * n] = 2.0 - omega * model.X[3 * n + 1];
    model.v0[3 * n + 1] = -1.0 + omega * model.X[3 * n];
    model.v0[3 * n + 2] = 0.5;
  }
  solver::Solver s(model);
  // One step: the stress is zero at t = 0, so v^{1/2} is still the linear field. (Later steps are not
  // a test of the hourglass vectors: the small stress of a finite rotation accelerates the nodes of a
  // warped element non-linearly, which legitimately feeds the hourglass modes.)
  const double ke = s.balance().kinetic();
  s.step();
  if (ihq == 1) {
    // IHQ 1 (raw base vectors) resists rotation of skewed elements (KW *HOURGLASS): documented.
    EXPECT_GT(s.state().hourglass_energy, 1e-9 * ke);
  } else {
    EXPECT_LT(std::abs(s.state().hourglass_energy), 1e-12 * ke);
  }
}

INSTANTIATE_TEST_SUITE_P(IHQ, HourglassMode, ::testing::Values(1, 2, 3, 4, 5, 6),
                         [](const auto& info) { return "IHQ" + std::to_string(info.param); });

// IHQ 6 (assumed strain, hourglass/assumed_strain.hpp): on a free cube of side h the 12
// hourglass modes are uncoupled except the three shear ones (u_x ~ eta zeta, u_y ~ zeta xi,
// u_z ~ xi eta). A normal mode of amplitude q (nodal displacement q Gamma) has the energy
// W = QM (V/3) E (q/a)^2 / 2 (a = h/2; V/9 for xi eta zeta), its mass is rho V (8 nodes of rho V/8
// moving q), so it oscillates at omega^2 = QM E / (3 rho a^2) (1/3 of that for xi eta zeta). The
// one-point stress does not see the mode (gamma is orthogonal to every linear field). Measured:
// the period of the nodal velocity from its zero crossings, against the central-difference period
// of that oscillator, 2 pi / omega_d with sin(omega_d dt/2) = omega dt/2 (the scheme's exact
// discrete frequency for a linear oscillator). Tolerance 1e-3: the zero crossings are
// interpolated linearly between steps (~ (omega dt)^2 / 8 of a step of the period, dt ~ T/60) and
// the element's geometry changes by the amplitude 1e-6 h.
struct Ihq6Mode {
  int component, alpha;
  double factor;  // 1 for the linear terms, 1/3 for xi eta zeta
};

class Ihq6NormalMode : public ::testing::TestWithParam<Ihq6Mode> {};

TEST_P(Ihq6NormalMode, OscillatesAtTheAssumedStrainFrequency) {
  const Ihq6Mode mode = GetParam();
  // TSSFAC 0.1: ~60 steps per period for the zero-crossing interpolation, and a lone free element
  // is unstable in its dilatation mode at 0.9 (README, "Instability guard"), which round-off excites.
  std::string yaml = cube_yaml(6);
  yaml.replace(yaml.find("QM: 0.1"), 7, "QM: 1.0");
  yaml.replace(yaml.find("termination_time: 1}"), 20, "termination_time: 1, tssfac: 0.1}");
  model::Model model = test::model_from_yaml(yaml);
  const double h = 0.01, a = h / 2, rho = 7800, E = 200e9;
  const double omega = std::sqrt(mode.factor * E / (3 * rho * a * a));
  const double v0 = 1e-6 * h * omega;
  const Index* conn = model.blocks[0].conn.data();
  for (int k = 0; k < 8; ++k) model.v0[3 * std::size_t(conn[k]) + mode.component] = v0 * element::kGamma[mode.alpha][k];
  solver::Solver s(model);
  const std::size_t probe = 3 * std::size_t(conn[0]) + mode.component;  // Gamma_k(0) = +-1
  const double sign = element::kGamma[mode.alpha][0];
  double t_prev = 0, v_prev = sign * s.state().v[probe], t_first = -1, t_third = -1;
  int crossings = 0;
  double dt = 0;
  while (crossings < 3 && s.state().time < 10.0 / omega) {
    s.step();
    dt = s.state().dt_prev_half;
    const double t = s.state().time - 0.5 * dt;  // v is at mid-step
    const double vv = sign * s.state().v[probe];
    if ((v_prev > 0) != (vv > 0)) {
      const double tc = t_prev + (t - t_prev) * v_prev / (v_prev - vv);
      if (++crossings == 1) t_first = tc;
      if (crossings == 3) t_third = tc;
    }
    t_prev = t, v_prev = vv;
  }
  ASSERT_EQ(crossings, 3) << "the mode is not resisted (no oscillation)";
  const double omega_d = 2 / dt * std::asin(omega * dt / 2);
  const double period = t_third - t_first;
  EXPECT_NEAR(period, 2 * M_PI / omega_d, 1e-3 * 2 * M_PI / omega_d)
      << "component " << mode.component << " alpha " << mode.alpha;
}

INSTANTIATE_TEST_SUITE_P(IHQ6, Ihq6NormalMode,
                         ::testing::Values(Ihq6Mode{0, 0, 1}, Ihq6Mode{0, 2, 1}, Ihq6Mode{0, 3, 1.0 / 3},
                                           Ihq6Mode{1, 0, 1}, Ihq6Mode{1, 1, 1}, Ihq6Mode{1, 3, 1.0 / 3},
                                           Ihq6Mode{2, 1, 1}, Ihq6Mode{2, 2, 1}, Ihq6Mode{2, 3, 1.0 / 3}),
                         [](const auto& info) {
                           std::string name = "u";  // (appending: avoids a GCC 12 -Wrestrict false positive)
                           name += "xyz"[info.param.component];
                           name += "_alpha";
                           name += std::to_string(info.param.alpha);
                           return name;
                         });

// IHQ 6 moduli of an orthotropic ply (T300/epoxy-like MAT_002, the patch test's constants) on a
// cube whose element frame is x, y, z, with the fibre a along x (0 deg) and at 45 deg in the x-y
// plane. Reference: the off-axis engineering constants of a lamina (Jones, Mechanics of Composite
// Materials, 2nd ed., eq. 2.97): 1/E_x = c^4/E1 + s^4/E2 + (1/G12 - 2 nu12/E1) s^2 c^2 and
// 1/G_xy = 2 (2/E1 + 2/E2 + 4 nu12/E1 - 1/G12) s^2 c^2 + (s^4 + c^4)/G12; the transverse shear
// moduli rotate as 1/G_yz = c^2/G23 + s^2/G13. Tolerance 1e-12 relative (a 3x3 inverse).
TEST(AssumedStrainModuli, OffAxisPlyMatchesLaminaTransformation) {
  const double E1 = 157e9, E2 = 8.5e9, nu21 = 0.019, G12 = 4.2e9, G23 = 2.2e9, G13 = 4.2e9;
  const double nu12 = nu21 * E1 / E2;  // PRBA is the minor ratio nu_ba
  for (const double deg : {0.0, 45.0}) {
    const double th = deg * M_PI / 180, c = std::cos(th), s = std::sin(th);
    std::ostringstream y;
    y << "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      << "  m: {card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      << " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [" << c << ", " << s << ", 0], D: [" << -s << ", " << c
      << ", 0]}\nsections:\n  s: {ELFORM: 1, IHQ: 6, QM: 1}\nparts:\n  p: {material: m, section: s}\n"
      << "mesh:\n  boxes:\n    - {part: p, size: [0.01, 0.02, 0.005], elements: [1, 1, 1]}\n";
    const model::Model model = test::model_from_yaml(y.str());
    const std::vector<double> m = hourglass::assumed_strain_moduli(model, model.blocks[0]);
    const double c2 = c * c, s2 = s * s;
    const double Ex = 1 / (c2 * c2 / E1 + s2 * s2 / E2 + (1 / G12 - 2 * nu12 / E1) * s2 * c2);
    const double Ey = 1 / (s2 * s2 / E1 + c2 * c2 / E2 + (1 / G12 - 2 * nu12 / E1) * s2 * c2);
    const double Gxy = 1 / (2 * (2 / E1 + 2 / E2 + 4 * nu12 / E1 - 1 / G12) * s2 * c2 + (s2 * s2 + c2 * c2) / G12);
    const double Gyz = 1 / (c2 / G23 + s2 / G13), Gzx = 1 / (c2 / G13 + s2 / G23);
    const double expected[6] = {Ex, Ey, E2, Gxy, Gyz, Gzx};
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(m[i], expected[i], 1e-12 * expected[i]) << deg << " deg, modulus " << i;
  }
}

// A ply whose matrix failed (material::lost_component bb and ab, the degradation table's E_b = 0,
// nu = 0 on b, G_ab = 0) keeps its fibre: the IHQ 6 moduli are the same lamina transformation with
// E2 -> r E2, G12 -> r G12 and nu12 -> 0 (r = kLostComponentResidual), the through-thickness
// modulus E3 unchanged and no coupling to b. Fibre-compression failure (aa lost) leaves the
// transverse moduli. Tolerance 1e-12 relative, as above.
TEST(AssumedStrainModuli, LostComponentsLeaveTheDegradedLamina) {
  namespace L = material::lost_component;
  const double E1 = 157e9, E2 = 8.5e9, E3 = 8.5e9, G12 = 4.2e9, G23 = 2.2e9, G13 = 4.2e9;
  const double r = hourglass::kLostComponentResidual;
  for (const double deg : {0.0, 45.0}) {
    const double th = deg * M_PI / 180, c = std::cos(th), s = std::sin(th);
    std::ostringstream y;
    y << "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      << "  m: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      << " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, XT: 2.2e9, XC: 1.2e9, YT: 45e6, YC: 280e6, SC: 45e6, AOPT: 2, A: ["
      << c << ", " << s << ", 0], D: [" << -s << ", " << c << ", 0]}\nsections:\n  s: {ELFORM: 1, IHQ: 6, QM: 1}\n"
      << "parts:\n  p: {material: m, section: s}\n"
      << "mesh:\n  boxes:\n    - {part: p, size: [0.01, 0.02, 0.005], elements: [1, 1, 1]}\n";
    const model::Model model = test::model_from_yaml(y.str());
    double m[6];
    hourglass::assumed_strain_element_moduli(model, model.blocks[0], 0, L::kBb | L::kAb, m);
    const double c2 = c * c, s2 = s * s, E2d = r * E2, G12d = r * G12;
    const double Ex = 1 / (c2 * c2 / E1 + s2 * s2 / E2d + s2 * c2 / G12d);
    const double Ey = 1 / (s2 * s2 / E1 + c2 * c2 / E2d + s2 * c2 / G12d);
    const double Gxy = 1 / (2 * (2 / E1 + 2 / E2d - 1 / G12d) * s2 * c2 + (s2 * s2 + c2 * c2) / G12d);
    const double Gyz = 1 / (c2 / G23 + s2 / G13), Gzx = 1 / (c2 / G13 + s2 / G23);
    // E_z' = 1/S_cc: the c row keeps only its coupling to a, which a uniaxial c stress does not see.
    const double expected[6] = {Ex, Ey, E3, Gxy, Gyz, Gzx};
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(m[i], expected[i], 1e-12 * expected[i]) << deg << " deg, modulus " << i;
    if (deg == 0) {
      hourglass::assumed_strain_element_moduli(model, model.blocks[0], 0, L::kAa, m);
      EXPECT_NEAR(m[0], r * E1, 1e-12 * r * E1);
      EXPECT_NEAR(m[1], E2, 1e-12 * E2);
      EXPECT_NEAR(m[3], G12, 1e-12 * G12);
    }
  }
}

// rescale_assumed_strain_forces: the stored forces of an element with half-lengths (a, b, c) built
// from normal-mode forces N and generalised shear forces S (the kernel's Q_x1 = Sxy/b + Szx/c,
// Q_y2 = Sxy/a + Syz/c, Q_z0 = Syz/b + Szx/a) become those built from N and S times each modulus'
// ratio. Tolerance 1e-12 relative (a 3x3 solve).
TEST(AssumedStrainModuli, RescaledForcesFollowEachModulus) {
  const double a = 1.25e-3, b = 2.5e-3, c = 0.125e-3;
  const double m_old[6] = {10, 20, 30, 4, 5, 6}, m_new[6] = {10, 0.02, 15, 0.004, 5, 3};
  const double sxy = 3.0, syz = -2.0, szx = 0.5;
  auto build = [&](const double (&ratio)[6], double (&Q)[12]) {
    for (int i = 0; i < 12; ++i) Q[i] = 0.1 * (i + 1) * ratio[i == 0 || i == 2 || i == 3 ? 0 : i < 8 ? 1 : 2];
    const double txy = ratio[3] * sxy, tyz = ratio[4] * syz, tzx = ratio[5] * szx;
    Q[1] = txy / b + tzx / c;
    Q[6] = txy / a + tyz / c;
    Q[8] = tyz / b + tzx / a;
  };
  const double ones[6] = {1, 1, 1, 1, 1, 1};
  double ratio[6], Q[12], expected[12];
  for (int i = 0; i < 6; ++i) ratio[i] = m_new[i] / m_old[i];
  build(ones, Q);
  build(ratio, expected);
  hourglass::rescale_assumed_strain_forces(Q, m_old, m_new, a, b, c);
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(Q[i], expected[i], 1e-12 * std::abs(expected[i]) + 1e-15) << "force " << i;
}

}  // namespace
}  // namespace plyimpact
