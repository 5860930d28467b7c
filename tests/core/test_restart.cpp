// One run state (solver visit_state, core/state_io): a run interrupted after N cycles, its state
// written and read into a freshly built solver, continues exactly as the uninterrupted run. The
// reference is the uninterrupted run itself; the comparison is bit for bit (energies, positions,
// velocities every cycle, and the digest of the whole state), because the continued run executes
// the same arithmetic on the same values: any member left out of the state shows as a difference.
// Scenes: a bar driven by a prescribed velocity with IHQ 4 (stiffness hourglass forces carried
// between steps), a rod with gravity on a rigid wall (the wall's held nodes and energy, gravity's
// work), and a *MAT_054 bar pulled until an element erodes (alive masks, damage history and the
// crashfront flags of its neighbours). Penalty contact joins once PenaltyContact names its state.
#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

#include "core/error.hpp"
#include "core/state_io.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

std::uint64_t digest(solver::Solver& s) {
  StateDigest d;
  s.visit_state(d);
  return d.value();
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

bool same_balance(const solver::Energies& a, const solver::Energies& b) {
  if (a.terms.size() != b.terms.size() || std::memcmp(&a.time, &b.time, sizeof a.time) != 0) return false;
  for (std::size_t i = 0; i < a.terms.size(); ++i)
    if (std::memcmp(&a.terms[i].value, &b.terms[i].value, sizeof(double)) != 0) return false;
  return true;
}

// Runs `first` cycles, restarts into a new solver, runs `more` cycles on both; everything equal.
void expect_restart_identical(const std::string& yaml, long first, long more) {
  const model::Model model = test::model_from_yaml(yaml, "restart.yaml");
  solver::Solver a(model);
  for (long i = 0; i < first; ++i) a.step();
  std::stringstream file;
  StateWriter writer(file);
  a.visit_state(writer);

  solver::Solver b(model);
  StateReader reader(file, "restart.state");
  b.visit_state(reader);
  ASSERT_EQ(digest(a), digest(b));
  for (long i = 0; i < more; ++i) {
    a.step();
    b.step();
    ASSERT_TRUE(same_balance(a.balance(), b.balance())) << "balance differs " << i + 1 << " cycles after the restart";
    ASSERT_TRUE(same_bits(a.state().x, b.state().x)) << "x differs " << i + 1 << " cycles after the restart";
    ASSERT_TRUE(same_bits(a.state().v, b.state().v)) << "v differs " << i + 1 << " cycles after the restart";
  }
  EXPECT_EQ(digest(a), digest(b));
  EXPECT_GT(a.state().cycle, first);
}

const char* kBar = R"(units: mm-t-s-MPa
control: {termination_time: 1.5e-5}
materials:
  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}
sections:
  hex1: {ELFORM: 1, IHQ: 4, QM: 0.1}
parts:
  bar: {material: steel, section: hex1}
mesh:
  boxes:
    - {part: bar, size: [40, 2, 2], elements: [40, 2, 2]}
node_sets:
  left: {plane: {axis: x, value: 0}}
  all_nodes: all
boundary_conditions:
  - {node_set: all_nodes, fix: [y, z]}
  - {node_set: left, velocity: {dofs: [x], value: 10 m/s}}
)";

TEST(Restart, BarWaveContinuesBitForBit) { expect_restart_identical(kBar, 60, 80); }

// Mass scaling (control.dt2ms) is applied to the model before the run, not carried in the state:
// a restart rebuilds the model from the scene, so that rebuild must give the same masses bit for
// bit, and the continued run must then be the uninterrupted one. The bar's 1 mm cubes (1.7e-7 s)
// are scaled to 2.5e-7 s.
TEST(Restart, MassScaledBarContinuesBitForBit) {
  std::string yaml = kBar;
  const std::string control = "termination_time: 1.5e-5}";
  yaml.replace(yaml.find(control), control.size(), "termination_time: 1.5e-5, dt2ms: -2.5e-7 s}");
  const model::Model first = test::model_from_yaml(yaml, "bar.yaml");
  const model::Model rebuilt = test::model_from_yaml(yaml, "bar.yaml");
  ASSERT_GT(first.mass_scaling.total_added, 0);
  ASSERT_TRUE(same_bits(first.mass, rebuilt.mass));
  ASSERT_TRUE(same_bits(first.blocks[0].step_scale, rebuilt.blocks[0].step_scale));
  expect_restart_identical(yaml, 60, 80);
}

TEST(Restart, RodOnRigidWallWithGravityContinuesBitForBit) {
  // The rod reaches the wall (gap 0.1 mm at 10 m/s: 10 us, ~55 steps) before the restart, so the
  // wall holds nodes across it.
  const std::string yaml = std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
                           "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
                           "sections:\n  s: {ELFORM: 2, Q1: 0, Q2: 0}\n"
                           "parts:\n  rod: {material: steel, section: s}\n"
                           "mesh:\n  boxes:\n    - {part: rod, origin: [0, 0, 0.0001], size: [0.001, 0.001, 0.03], "
                           "elements: [1, 1, 30]}\n"
                           "node_sets:\n  all_nodes: all\n"
                           "boundary_conditions:\n  - {node_set: all_nodes, fix: [x, y]}\n"
                           "initial_velocity:\n  - {part: rod, velocity: [0, 0, -10]}\n"
                           "gravity: [0, 0, -9.81]\n"
                           "rigid_walls:\n  - {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}\n";
  const model::Model model = test::model_from_yaml(yaml, "rod.yaml");
  solver::Solver probe(model);
  long cycles = 0;
  while (probe.rigid_walls()[0].active_nodes() == 0 && cycles < 1000) probe.step(), ++cycles;
  ASSERT_LT(cycles, 1000) << "the rod never reached the wall";
  expect_restart_identical(yaml, cycles + 5, 60);
}

TEST(Restart, ErodedMat054BarContinuesBitForBit) {
  // Four T800 elements pulled along the fibres at 0.5 m/s (ramped over 20 us): one fails at XT
  // and is eroded; the restart comes a few cycles later.
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1.0e-4, tssfac: 0.6}\n"
      "materials:\n  m: {card: MAT_054, RO: 1550, EA: 165e9, EB: 7.64e9, EC: 7.64e9, PRBA: 0.0162, PRCA: 0.0162, "
      "PRCB: 0.4, GAB: 5.61e9, GBC: 2.75e9, GCA: 5.61e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], XC: 1200e6, "
      "XT: 2200e6, YC: 280e6, YT: 45e6, SC: 50e6, BETA: 1}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\nparts:\n  p: {material: m, section: s}\n"
      "mesh:\n  boxes:\n    - {part: p, size: [4.0e-3, 1.0e-3, 1.0e-3], elements: [4, 1, 1]}\n"
      "node_sets:\n  x0: {plane: {axis: x, value: 0}}\n  x1: {plane: {axis: x, value: 4.0e-3}}\n"
      "  y0: {plane: {axis: y, value: 0}}\n  z0: {plane: {axis: z, value: 0}}\n"
      "boundary_conditions:\n  - {node_set: x0, fix: [x]}\n  - {node_set: y0, fix: [y]}\n"
      "  - {node_set: z0, fix: [z]}\n"
      "  - {node_set: x1, velocity: {dofs: [x], curve: [[0, 0], [2.0e-5, 0.5], [1, 0.5]]}}\n";
  const model::Model model = test::model_from_yaml(yaml, "pull.yaml");
  solver::Solver probe(model);
  while (probe.state().eroded_elements == 0 && probe.state().cycle < 20000) probe.step();
  ASSERT_GT(probe.state().eroded_elements, 0) << "no element eroded";
  expect_restart_identical(yaml, probe.state().cycle + 3, 40);
}

TEST(Restart, StateOfAnotherModelIsRefusedWithTheBlockNamed) {
  const model::Model bar = test::model_from_yaml(kBar, "bar.yaml");
  std::string longer = kBar;
  longer.replace(longer.find("size: [40, 2, 2], elements: [40, 2, 2]"), 38, "size: [40, 2, 2], elements: [20, 2, 2]");
  const model::Model other = test::model_from_yaml(longer, "other.yaml");
  solver::Solver a(bar);
  std::stringstream file;
  StateWriter writer(file);
  a.visit_state(writer);
  solver::Solver b(other);
  StateReader reader(file, "bar.state");
  try {
    b.visit_state(reader);
    FAIL() << "a state of another model was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bar.state"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("solver/state/"), std::string::npos) << e.what();
  }
}

TEST(Restart, TruncatedStateIsRefused) {
  const model::Model bar = test::model_from_yaml(kBar, "bar.yaml");
  solver::Solver a(bar);
  std::stringstream file;
  StateWriter writer(file);
  a.visit_state(writer);
  std::stringstream cut(file.str().substr(0, file.str().size() / 2));
  solver::Solver b(bar);
  StateReader reader(cut, "cut.state");
  EXPECT_THROW(b.visit_state(reader), InputError);
}

}  // namespace
}  // namespace plyimpact
