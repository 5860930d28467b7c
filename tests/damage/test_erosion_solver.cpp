// Materials with failure inside the solver: a single *MAT_054 element pulled along its fibres
// fails at XT and is eroded (DFAILT = 0: fibre-tension failure deletes the layer); a *MAT_003
// element follows the bilinear law; a *MAT_003 bar pulled apart erodes and keeps its energy balance.
// The same with ELFORM 2 (eight points, each with its own history): a homogeneous pull gives every
// point the same state, so the element must reproduce the ELFORM 1 answers and closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "../core/support.hpp"
#include "material/composite_damage_output.hpp"
#include "material/plasticity.hpp"
#include "run/frame_material_fields.hpp"

namespace plyimpact {
namespace {

// Uniaxial stress on a unit cube (1 mm): x = 0 face held in x, y = 0 in y, z = 0 in z, the x = L
// face pulled at a velocity ramped over 2e-5 s to `v` (smooth start: small dynamic overshoot).
std::string pull_scene(const std::string& material, double v, double t_end, int nx = 1, int elform = 1) {
  return "units: SI\ncontrol: {termination_time: " + std::to_string(t_end) +
         ", tssfac: 0.6}\n"  // a lone element's Courant limit is below 0.9 (tests/core/test_stability.cpp)
         "materials:\n  m: " + material + "\nsections:\n  s: {ELFORM: " + std::to_string(elform) +
         (elform == 1 ? ", IHQ: 4" : "") + "}\nparts:\n  p: {material: m, section: s}\n"
         "mesh:\n  boxes:\n    - {part: p, size: [" + std::to_string(1e-3 * nx) + ", 1.0e-3, 1.0e-3], elements: [" +
         std::to_string(nx) + ", 1, 1]}\n"
         "node_sets:\n  x0: {plane: {axis: x, value: 0}}\n  x1: {plane: {axis: x, value: " + std::to_string(1e-3 * nx) +
         "}}\n  y0: {plane: {axis: y, value: 0}}\n  z0: {plane: {axis: z, value: 0}}\n"
         "boundary_conditions:\n  - {node_set: x0, fix: [x]}\n  - {node_set: y0, fix: [y]}\n  - {node_set: z0, fix: [z]}\n"
         "  - {node_set: x1, velocity: {dofs: [x], curve: [[0, 0], [2.0e-5, " + std::to_string(v) + "], [1, " +
         std::to_string(v) + "]]}}\n";
}

const char* kT800 =
    "{card: MAT_054, RO: 1550, EA: 165e9, EB: 7.64e9, EC: 7.64e9, PRBA: 0.0162, PRCA: 0.0162, PRCB: 0.4, GAB: 5.61e9,"
    " GBC: 2.75e9, GCA: 5.61e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], XC: 1200e6, XT: 2200e6, YC: 280e6, YT: 45e6,"
    " SC: 50e6, BETA: 1}";

class ErosionSolver : public ::testing::TestWithParam<int> {};  // parameter: ELFORM 1 or 2

TEST_P(ErosionSolver, Mat054ElementFailsAtXTAndIsEroded) {
  const int elform = GetParam(), points = elform == 2 ? 8 : 1;
  const model::Model model =
      test::model_from_yaml(pull_scene(kT800, 0.5, 1.0e-4, 1, elform), "mat054_pull.yaml");
  solver::Solver s(model);
  double peak = 0;
  long erosion_cycle = -1;
  while (s.state().time < 1.0e-4 && erosion_cycle < 0) {
    s.step();
    peak = std::max(peak, s.state().blocks[0].stress[0]);
    if (s.state().eroded_elements > 0) erosion_cycle = s.state().cycle;
  }
  ASSERT_GT(erosion_cycle, 0) << "the element should have failed in fibre tension";
  // Quasi-static pull (strain rate 500/s): the fibre stress peaks at XT. Tolerance 0.5 %: one step
  // of strain (v dt / L ~ 3e-5, i.e. 5 MPa) plus the dynamic overshoot rho c v ~ 5 MPa.
  std::cout << "MAT_054 peak fibre stress " << peak / 1e6 << " MPa (XT 2200), eroded at cycle " << erosion_cycle << "\n";
  EXPECT_NEAR(peak, 2200e6, 0.005 * 2200e6);
  EXPECT_EQ(s.state().eroded_elements, 1);
  ASSERT_EQ(s.state().erosion.size(), 1u);
  EXPECT_STREQ(solver::erosion_cause_name(s.state().erosion[0].cause), solver::erosion_cause_name(
      int(solver::ErosionCause::CompositeBase) + int(material::CompositeDamageCause::FibreTension)));
  // The output marks the element as eroded and carries the damage fields (fibre-tension flag 0).
  output::Frame frame;
  run::add_material_fields(s, frame);
  ASSERT_EQ(frame.cell_int_fields.size(), 1u);
  EXPECT_EQ(frame.cell_int_fields[0].name, "alive");
  EXPECT_EQ(frame.cell_int_fields[0].values[0], 0);
  ASSERT_EQ(frame.cell_fields.size(), std::size_t(material::kCompositeDamageOutputs));
  EXPECT_EQ(frame.cell_fields[0].values[0], 0.0) << frame.cell_fields[0].name;  // e_f: failed
  // After erosion the element carries nothing: the pulled face needs no force.
  for (int i = 0; i < 10; ++i) s.step();
  for (int g = 0; g < points; ++g) EXPECT_EQ(s.state().blocks[0].stress[6 * g], 0.0) << "point " << g;
  EXPECT_NEAR(s.state().reaction[0], 0.0, 1e-6);
}

TEST_P(ErosionSolver, Mat003ElementFollowsBilinearLaw) {
  const double E = 200e9, SIGY = 250e6, ETAN = 2e9;
  const int elform = GetParam(), points = elform == 2 ? 8 : 1;
  const model::Model model = test::model_from_yaml(
      pull_scene("{card: MAT_003, RO: 7850, E: 200e9, PR: 0.3, SIGY: 250e6, ETAN: 2e9}", 1.0, 1.2e-4, 1, elform),
      "mat003_pull.yaml");
  solver::Solver s(model);
  test::run_until(s, 1.2e-4);
  // Logarithmic axial strain of the element and the Cauchy stress: at ~10 % strain the bilinear law
  // in true stress / log strain is what a hypoelastic J2 update integrates (rate form). Tolerance
  // 1 %: dynamic start-up and the elastic lateral contraction.
  const double stretch = 1.0 + (s.state().x[3 * 1] - model.X[3 * 1]) / 1e-3;  // node 1 is at x = L
  const double eps = std::log(stretch);
  const double expected = SIGY + ETAN * (eps - SIGY / E);
  std::cout << "MAT_003 at log strain " << eps << ": stress " << s.state().blocks[0].stress[0] / 1e6 << " MPa, bilinear "
            << expected / 1e6 << " MPa, plastic strain " << s.state().blocks[0].history[0] << "\n";
  EXPECT_NEAR(s.state().blocks[0].stress[0], expected, 0.01 * expected) << "eps = " << eps;
  EXPECT_GT(s.state().blocks[0].history[0], 0.05);  // plastic strain accumulated
  // Homogeneous deformation: every point of an ELFORM 2 element holds the same state (round-off).
  for (int g = 1; g < points; ++g) {
    EXPECT_NEAR(s.state().blocks[0].stress[6 * g], s.state().blocks[0].stress[0], 1e-9 * expected) << "point " << g;
    EXPECT_NEAR(s.state().blocks[0].history[std::size_t(g) * material::kPlasticityHistory],
                s.state().blocks[0].history[0], 1e-9) << "point " << g;
  }
  // The output reports the mean plastic strain of the points.
  output::Frame frame;
  run::add_material_fields(s, frame);
  ASSERT_EQ(frame.cell_fields.size(), 1u);
  EXPECT_EQ(frame.cell_fields[0].name, "plastic_strain");
  EXPECT_NEAR(frame.cell_fields[0].values[0], s.state().blocks[0].history[0], 1e-9);
}

TEST_P(ErosionSolver, BarPulledApartKeepsEnergyBalance) {
  // Ten MAT_003 elements with FS = 2 %: all strain equally, the first to reach FS erodes and the
  // bar separates. Energy (kinetic + internal incl. eroded + hourglass + bulk) must still balance the
  // work of the pulling velocity: within 1 %.
  const model::Model model = test::model_from_yaml(
      pull_scene("{card: MAT_003, RO: 7850, E: 200e9, PR: 0.3, SIGY: 250e6, ETAN: 2e9, FS: 0.02}", 2.0, 2.0e-4, 10,
                 GetParam()),
      "bar_erosion.yaml");
  solver::Solver s(model);
  test::run_until(s, 2.0e-4);
  std::cout << "bar: " << s.state().eroded_elements << " eroded, eroded energy " << s.state().eroded_energy
            << " J, energy ratio " << s.energy_ratio() << ", external work " << s.balance().external_work() << " J\n";
  EXPECT_GE(s.state().eroded_elements, 1);
  EXPECT_GT(s.state().eroded_energy, 0.0);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 0.01);
}

TEST(ErosionSolverElform2, OneFailedPointErodesTheElement) {
  // A non-uniform pull: only the edge x = L, y = L of a cube is pulled, so the eight points strain
  // differently. Our rule for ELFORM 2 (as NUMFIP = 1): the element goes when its first point
  // reaches FS. At that cycle the most strained point is at FS and at least one other is below.
  const double FS = 0.05;
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1.0e-3, tssfac: 0.6}\n"
      "materials:\n  m: {card: MAT_003, RO: 7850, E: 200e9, PR: 0.3, SIGY: 250e6, ETAN: 2e9, FS: 0.05}\n"
      "sections:\n  s: {ELFORM: 2}\nparts:\n  p: {material: m, section: s}\n"
      "mesh:\n  boxes: [{part: p, size: [1.0e-3, 1.0e-3, 1.0e-3], elements: [1, 1, 1]}]\n"
      "node_sets:\n  x0: {plane: {axis: x, value: 0}}\n  y0: {plane: {axis: y, value: 0}}\n"
      "  z0: {plane: {axis: z, value: 0}}\n  edge: {box: {min: [1.0e-3, 1.0e-3, 0], max: [1.0e-3, 1.0e-3, 1.0e-3]}}\n"
      "boundary_conditions:\n  - {node_set: x0, fix: [x]}\n  - {node_set: y0, fix: [y]}\n  - {node_set: z0, fix: [z]}\n"
      "  - {node_set: edge, velocity: {dofs: [x], curve: [[0, 0], [2.0e-5, 1.0], [1, 1.0]]}}\n";
  const model::Model model = test::model_from_yaml(yaml, "elform2_edge_pull.yaml");
  solver::Solver s(model);
  while (s.state().time < 1.0e-3 && s.state().eroded_elements == 0) s.step();
  ASSERT_EQ(s.state().eroded_elements, 1);
  double ep_min = 1e9, ep_max = 0;
  for (int g = 0; g < 8; ++g) {
    const double ep = s.state().blocks[0].history[std::size_t(g) * material::kPlasticityHistory];
    ep_min = std::min(ep_min, ep), ep_max = std::max(ep_max, ep);
  }
  std::cout << "ELFORM 2 edge pull: eroded at cycle " << s.state().cycle << ", plastic strain of the points "
            << ep_min << " .. " << ep_max << " (FS " << FS << ")\n";
  EXPECT_GE(ep_max, FS);
  EXPECT_LT(ep_min, FS);
  EXPECT_STREQ(solver::erosion_cause_name(s.state().erosion[0].cause), "plastic_strain");
  for (int i = 0; i < 48; ++i) EXPECT_EQ(s.state().blocks[0].stress[i], 0.0);
}

INSTANTIATE_TEST_SUITE_P(Elform, ErosionSolver, ::testing::Values(1, 2),
                         [](const auto& info) { return "ELFORM" + std::to_string(info.param); });

}  // namespace
}  // namespace plyimpact
