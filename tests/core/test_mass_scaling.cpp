// Mass scaling (*CONTROL_TIMESTEP DT2MS < 0, solver/mass_scaling): an element whose stable step dt_e
// is below |DT2MS| gets dm_e = m_e ((|DT2MS| / dt_e)^2 - 1) on its nodes, its step becomes |DT2MS|.
// Independent answers: (1) the bookkeeping against the closed form (cubes and flat boxes at rest
// have dt_e = L / c, L = V / A_max, exactly) and against the sum of the nodal mass changes; (2) the
// step the solver takes; (3) the kinetic energy of the added mass at t = 0 against 1/2 (M + dM) v^2
// and the energy balance through an impact; (4) a bar's wave speed against c sqrt(m0 / (m0 + dm));
// (5) one and two threads bit-identical with contact, erosion and a rigid body (test_threads.cpp,
// MassScaledImpactIsBitIdentical) and the restart (test_restart.cpp, MassScaledBarContinuesBitForBit),
// each in that file's bit-for-bit harness.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "solver/element_update.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

// A number for an inline scene, exactly (std::to_string prints fixed-point with 6 decimals).
std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

constexpr double kSteelM = 210e9 * 0.7 / (1.3 * 0.4);  // P-wave modulus lambda + 2 mu, E 210 GPa, nu 0.3

// A 10 x 10 x 4 mm block of 1 mm cubes (dt = 1 mm / c) under a 0.5 mm skin of 1 x 1 x 0.5 mm
// elements (dt = 0.5 mm / c), steel; the skin moves at `vz`.
std::string two_part_block(double dt2ms, double vz = 0, const std::string& extra = "") {
  return "units: SI\ncontrol: {termination_time: 1e-3, dt2ms: " + num(dt2ms) + extra +
         "}\nmaterials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: 4}\nparts:\n  core: {material: steel, section: s}\n"
         "  skin: {material: steel, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: core, size: [0.01, 0.01, 0.004], elements: [10, 10, 4]}\n"
         "    - {part: skin, origin: [0, 0, 0.004], size: [0.01, 0.01, 0.0005], elements: [10, 10, 1]}\n"
         "initial_velocity:\n  - {part: skin, velocity: [0, 0, " + num(vz) + "]}\n";
}

const model::PartAddedMass& part_named(const model::Model& m, const std::string& name) {
  for (const auto& p : m.mass_scaling.parts)
    if (m.parts[p.part].name == name) return p;
  throw std::runtime_error("no part " + name);
}

// (1), (2): 1.2e-7 s lies between the skin's step (8.6e-8 s) and the core's (1.7e-7 s).
TEST(MassScaling, AddedMassIsTheClosedFormAndTheNodalChange) {
  const double target = 1.2e-7;
  const model::Model plain = test::model_from_yaml(two_part_block(0), "plain.yaml");
  const model::Model scaled = test::model_from_yaml(two_part_block(-target), "scaled.yaml");
  const double c = scaled.materials[0].wave_speed;
  ASSERT_NEAR(c, std::sqrt(kSteelM / 7850), 1e-9 * c);
  const double dt_skin = 0.5e-3 / c, dt_core = 1e-3 / c;
  ASSERT_LT(dt_skin, target);
  ASSERT_GT(dt_core, target);

  const auto& r = scaled.mass_scaling;
  ASSERT_TRUE(r.applied);
  EXPECT_EQ(r.target, target);
  const auto& skin = part_named(scaled, "skin");
  const auto& core = part_named(scaled, "core");
  // Closed form: every skin element has dt = 0.5 mm / c; its mass rho V (V exact for a box).
  const double m_skin = 7850 * 0.01 * 0.01 * 0.0005, m_core = 7850 * 0.01 * 0.01 * 0.004;
  const double dm_skin = m_skin * ((target / dt_skin) * (target / dt_skin) - 1);
  // Sums of 100-800 terms: 1e-12 relative covers their round-off.
  EXPECT_NEAR(skin.mass, m_skin, 1e-12 * m_skin);
  EXPECT_NEAR(core.mass, m_core, 1e-12 * m_core);
  EXPECT_NEAR(skin.added, dm_skin, 1e-12 * dm_skin);
  EXPECT_EQ(skin.scaled_elements, 100);
  EXPECT_EQ(core.added, 0.0);
  EXPECT_EQ(core.scaled_elements, 0);
  // What is reported is what the nodes got: the sum of the nodal mass changes.
  double nodal_change = 0, plain_total = 0;
  for (std::size_t n = 0; n < plain.num_nodes(); ++n) {
    nodal_change += scaled.mass[n] - plain.mass[n];
    plain_total += plain.mass[n];
  }
  EXPECT_NEAR(nodal_change, r.total_added, 1e-12 * r.total_added);
  EXPECT_EQ(r.total_added, skin.added + core.added);
  EXPECT_NEAR(r.total_mass, plain_total, 1e-12 * plain_total);
  // A 5 % part-level limit: the skin (+94 %) is warned about, by name.
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("skin +"), std::string::npos) << r.warnings[0];

  // The element family's own step, after scaling: the skin's elements at the target (one rounding
  // of dt * (target / dt): 1e-15 relative), the core's untouched (bit-equal).
  for (std::size_t b = 0; b < scaled.blocks.size(); ++b) {
    const auto before = solver::initial_element_steps(plain, b);
    const auto after = solver::initial_element_steps(scaled, b);
    const bool is_skin = scaled.parts[scaled.blocks[b].part].name == "skin";
    for (std::size_t e = 0; e < after.size(); ++e) {
      if (is_skin) ASSERT_NEAR(after[e], target, 1e-15 * target) << "skin element " << e;
      else ASSERT_EQ(after[e], before[e]) << "core element " << e;
    }
  }
  // The solver's step: TSSFAC times the target (the skin controls; no springs).
  const solver::Solver s(scaled);
  EXPECT_NEAR(s.state().dt_next_half, scaled.control.tssfac * target, 1e-15 * target);

  // Applying twice adds nothing more.
  model::Model again = scaled;
  solver::apply_mass_scaling(again);
  EXPECT_EQ(std::memcmp(again.mass.data(), scaled.mass.data(), scaled.mass.size() * sizeof(double)), 0);
}

TEST(MassScaling, EndmasRefusesTooMuchAddedMass) {
  // ENDMAS is a percentage of the model's mass: just below the added fraction refuses, just above runs.
  const double percent = 100 * test::model_from_yaml(two_part_block(-1.2e-7)).mass_scaling.total_fraction();
  ASSERT_GT(percent, 1);
  EXPECT_THROW(test::model_from_yaml(two_part_block(-1.2e-7, 0, ", endmas: " + num(0.99 * percent))),
               InputError);
  EXPECT_NO_THROW(test::model_from_yaml(two_part_block(-1.2e-7, 0, ", endmas: " + num(1.01 * percent))));
}

TEST(MassScaling, PositiveOrTooLongDt2msIsRefusedAtItsLine) {
  for (const char* value : {"1e-7", "-2e-3"}) {
    try {
      test::model_from_yaml(std::string("units: SI\ncontrol:\n  termination_time: 1e-3\n  dt2ms: ") + value +
                                "\nmaterials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
                                "sections:\n  s: {ELFORM: 1}\nparts:\n  p: {material: steel, section: s}\n"
                                "mesh:\n  boxes:\n    - {part: p, size: [0.01, 0.01, 0.01], elements: [2, 2, 2]}\n",
                            "dt2ms.yaml");
      ADD_FAILURE() << "dt2ms " << value << " accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("dt2ms.yaml:4:"), std::string::npos) << what;
      EXPECT_NE(what.find("[-0.001, 0]"), std::string::npos) << what;
    }
  }
}

// (3) A steel bar in uniaxial strain (y, z fixed) strikes a fixed support at x = 0 at 10 m/s: its
// first 20 mm are 0.5 x 1 x 1 mm elements (dt 8.3e-8 s), scaled to 1.2e-7 s (+107 % mass), the
// other 60 mm 1 mm cubes (1.7e-7 s), unscaled. The support's node is held (no work), so the energy is
// conserved exactly in the continuum, and the front runs through the mass jump at 20 mm (part
// reflected). The added mass holds 21 % of the kinetic energy: were it not booked (or the dynamics run on
// another mass than the balance books), the ratio would be off by that much.
TEST(MassScaling, KineticEnergyOfTheAddedMassIsInTheBalanceOfAnImpact) {
  const double target = 1.2e-7, v = 10;
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1e-3, dt2ms: -1.2e-7}\n"
      "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\nparts:\n  fine: {material: steel, section: s}\n"
      "  coarse: {material: steel, section: s}\n"
      "mesh:\n  boxes:\n"
      "    - {part: fine, size: [0.02, 0.001, 0.001], elements: [40, 1, 1]}\n"
      "    - {part: coarse, origin: [0.02, 0, 0], size: [0.06, 0.001, 0.001], elements: [60, 1, 1]}\n"
      "node_sets:\n  support: {plane: {axis: x, value: 0}}\n  all_nodes: all\n"
      "boundary_conditions:\n  - {node_set: all_nodes, fix: [y, z]}\n  - {node_set: support, fix: [x]}\n"
      "initial_velocity:\n  - {part: fine, velocity: [-10, 0, 0]}\n  - {part: coarse, velocity: [-10, 0, 0]}\n";
  const model::Model model = test::model_from_yaml(yaml, "bar_impact.yaml");
  const auto& fine = part_named(model, "fine");
  const auto& coarse = part_named(model, "coarse");
  ASSERT_EQ(fine.scaled_elements, 40);
  ASSERT_EQ(coarse.scaled_elements, 0);
  // Fine: L = V / A_max = 0.5 mm, dt = 0.5 mm / c.
  const double c = std::sqrt(kSteelM / 7850), ratio = target * c / 0.5e-3;
  EXPECT_NEAR(fine.added, fine.mass * (ratio * ratio - 1), 1e-12 * fine.added);

  solver::Solver s(model);
  // t = 0: everything moves but the support's nodes (mass rho A h / 2 of the first fine layer,
  // scaled): 1/2 (M + dM - m_support) v^2. 1e-12: sums of ~500 terms.
  const double m_support = (fine.mass + fine.added) / 40 / 2;
  const double ke0 = 0.5 * (fine.mass + coarse.mass + fine.added - m_support) * v * v;
  EXPECT_NEAR(s.balance().value("kinetic"), ke0, 1e-12 * ke0);
  // The first element is compressed at tr D = -v / 0.5 mm by the held support, so its step carries
  // the bulk viscosity: the scaled step is the factor |DT2MS| / dt_e (dt_e at rest) times the damped
  // limit L / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 L |tr D|, the conservative product
  // (docs/theory.md, "Mass scaling"). 1e-12: a few roundings.
  {
    const double cm = model.materials[0].wave_speed, L = 0.5e-3, Q = 0.06 * cm + 1.5 * L * (v / L);
    const double expected = model.control.tssfac * (target * cm / L) * L / (Q + std::sqrt(Q * Q + cm * cm));
    EXPECT_NEAR(s.state().dt_next_half, expected, 1e-12 * expected);
  }
  double worst = 0, min_kinetic = ke0;
  const double t_end = 2 * 0.08 / c;  // the front crosses the bar twice: reflection at the free end
  while (s.state().time < t_end) {
    s.step();
    worst = std::max(worst, std::abs(s.energy_ratio() - 1));
    min_kinetic = std::min(min_kinetic, s.balance().value("kinetic"));
  }
  std::cout << "bar impact with mass scaling: " << s.state().cycle << " cycles, max |energy ratio - 1| " << worst
            << ", kinetic energy down to " << min_kinetic / ke0 << " of " << ke0 << " J\n";
  ASSERT_LT(min_kinetic, 0.5 * ke0) << "the impact did not stop the bar: the test does not exercise the balance";
  // Elastic, no contact: what remains is the central-difference energy error of the fronts and
  // the bulk viscosity's booking. Measured 1.3e-3 here and 8.2e-4 for the same bar unscaled (whose
  // coarse part runs at half the Courant number the fine part allows); at TSSFAC 0.6 they fall to
  // 4.8e-4 and 2.8e-4, i.e. it is the step's discretisation error, not a booking term. 2e-3 is
  // 100 times below the 21 % of the kinetic energy the added mass holds.
  EXPECT_LT(worst, 2e-3);
}

// (4) Uniaxial-strain steel bar of 400 cubes (h = 1 mm) pushed at 1 m/s at x = 0, every element
// scaled from h / c to 2 h / c: dm = 3 m0, so the front must run at c sqrt(m0 / (m0 + dm)) = c / 2.
// Measured as in test_wave_speed.cpp: the time the element stress passes half the plateau at two
// stations 99 h apart. The Courant number c' dt' / h is the unscaled 0.9, so that test's bound
// applies: 0.25 h over the 99 h, plus the finite-strain front speed U = c' (1 - e/4), e = -v0/c'.
TEST(MassScaling, BarWaveSpeedDropsBySqrtOfTheMassRatio) {
  constexpr int kN = 400;
  constexpr double kH = 1e-3, kV0 = 1.0;
  const double c = std::sqrt(kSteelM / 7850);
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1.0, dt2ms: " + num(-2 * kH / c) +
      "}\nmaterials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4, QM: 0.1, Q1: 1.5, Q2: 0.06}\nparts:\n  bar: {material: steel, section: s}\n"
      "mesh:\n  boxes:\n    - {part: bar, size: [0.4, 0.001, 0.001], elements: [400, 1, 1]}\n"
      "node_sets:\n  left: {plane: {axis: x, value: 0}}\n  all_nodes: all\n"
      "boundary_conditions:\n  - {node_set: all_nodes, fix: [y, z]}\n"
      "  - {node_set: left, velocity: {dofs: [x], value: 1.0}}\n";
  const model::Model model = test::model_from_yaml(yaml, "bar.yaml");
  const auto& bar = model.mass_scaling.parts.at(0);
  ASSERT_EQ(bar.scaled_elements, kN);
  ASSERT_NEAR(bar.added / bar.mass, 3.0, 1e-12);
  const double c_scaled = c * std::sqrt(bar.mass / (bar.mass + bar.added));
  const double U = c_scaled * (1 - 0.25 * (-kV0 / c_scaled));  // MAT_001: beta = -1/2 (test_wave_speed.cpp)
  auto centroid_x = [&](std::size_t e) {
    double x = 0;
    for (int k = 0; k < 8; ++k) x += model.X[3 * std::size_t(model.blocks[0].conn[8 * e + k])];
    return x / 8;
  };
  const std::size_t e1 = kN / 4, e2 = kN / 2 - 1;
  const double x1 = centroid_x(e1), x2 = centroid_x(e2);
  solver::Solver s(model);
  const double threshold = -0.5 * 4 * 7850 * c_scaled * kV0;  // half of rho' c' v0, rho' = 4 rho
  const auto& stress = s.state().blocks[0].stress;
  double t1 = -1, t2 = -1, prev1 = 0, prev2 = 0, t_prev = 0;
  while (s.state().time < 0.75 * kN * kH / c_scaled) {
    s.step();
    const double t = s.state().time, s1 = stress[6 * e1], s2 = stress[6 * e2];
    if (t1 < 0 && s1 <= threshold) t1 = t_prev + (t - t_prev) * (prev1 - threshold) / (prev1 - s1);
    if (t2 < 0 && s2 <= threshold) t2 = t_prev + (t - t_prev) * (prev2 - threshold) / (prev2 - s2);
    prev1 = s1, prev2 = s2, t_prev = t;
  }
  ASSERT_GT(t1, 0);
  ASSERT_GT(t2, 0);
  const double measured = (x2 - x1) / (t2 - t1);
  std::cout << "bar: front " << measured << " m/s, c sqrt(m0/(m0+dm)) = " << c_scaled << " m/s (unscaled c " << c
            << "), error " << (measured - U) / U << "\n";
  EXPECT_LT(std::abs(measured - U) / U, 0.25 * kH / (x2 - x1));
}

}  // namespace
}  // namespace plyimpact
