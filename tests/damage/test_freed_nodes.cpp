// Nodes that erosion leaves with nothing acting on them leave the calculation (solver.hpp,
// Solver::remove_freed_nodes), as LS-DYNA's ENMASS 0 removes them. Reference: conservation of
// energy and momentum, exactly. A bar of two steel elements flies free at v = (3, -4, 12) m/s
// (|v| = 13 m/s, nothing strains it); deleting its second element leaves the four nodes of its far
// face without elements, while the shared face stays held by the first element (TSSFAC 0.6: a lone
// element is beyond its Courant limit at 0.9 and grows round-off into motion). Then:
//  - those four nodes, and only those, are removed: velocity zero, positions frozen from then on;
//  - the eroded kinetic energy is what they carried, 4 (m / 2) |v|^2 with m their lumped mass, and
//    the kinetic energy left is that of the rest, (M - 4 m) |v|^2 / 2;
//  - the total energy keeps its value: energy ratio 1 to 1e-14 (round-off of a few sums) over 50
//    cycles;
//  - a state written after the removal and read into a new solver continues bit-identically, under
//    gravity too (which the removed nodes no longer feel: their inverse mass comes back as zero).
// ENMASS 1, where a contact holds such nodes as mass points, is tested with the contact
// (tests/contact/test_contact_paths.cpp, Enmass).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/state_io.hpp"
#include "solver/solver.hpp"
#include "../core/support.hpp"

namespace plyimpact {
namespace {

const char* kBar =
    "units: SI\ncontrol: {termination_time: 1.0, tssfac: 0.6}\n"
    "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
    "sections:\n  s: {ELFORM: 2}\n"
    "parts:\n  bar: {material: steel, section: s}\n"
    "mesh:\n  boxes:\n    - {part: bar, size: [0.002, 0.001, 0.001], elements: [2, 1, 1]}\n"
    "initial_velocity:\n  - {part: bar, velocity: [3, -4, 12]}\n";

TEST(FreedNodes, LeaveTheCalculationWithTheKineticEnergyTheyCarried) {
  const model::Model model = test::model_from_yaml(kBar, "bar.yaml");
  solver::Solver solver(model);
  for (int k = 0; k < 5; ++k) solver.step();
  solver.delete_elements({2});  // x in [1, 2] mm

  const auto& s = solver.state();
  double m_far = 0, m_total = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i) {
    m_total += model.mass[i];
    const bool far = std::abs(model.X[3 * i] - 0.002) < 1e-12;
    if (far) m_far += model.mass[i];
    EXPECT_EQ(!s.removed_nodes.empty() && s.removed_nodes[i], far) << "node " << i;
  }
  EXPECT_EQ(s.removed_node_count(), 4);
  constexpr double v2 = 13.0 * 13.0;
  EXPECT_NEAR(s.eroded_kinetic_energy, 0.5 * m_far * v2, 1e-14 * 0.5 * m_total * v2);

  const std::vector<double> x_removed = s.x;
  for (int k = 0; k < 50; ++k) solver.step();
  EXPECT_NEAR(solver.energy_ratio(), 1.0, 1e-14);
  EXPECT_NEAR(solver.balance().kinetic(), 0.5 * (m_total - m_far) * v2, 1e-14 * 0.5 * m_total * v2);
  EXPECT_EQ(solver.balance().value("eroded_kinetic"), s.eroded_kinetic_energy);
  for (std::size_t i = 0; i < model.num_nodes(); ++i) {
    if (!s.removed_nodes[i]) continue;
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(s.x[3 * i + d], x_removed[3 * i + d]);
      EXPECT_EQ(s.v[3 * i + d], 0.0);
    }
  }
}

TEST(FreedNodes, ARestartedRunKeepsThemRemoved) {
  const model::Model model = test::model_from_yaml(std::string(kBar) + "gravity: [0, 0, -1e4]\n", "bar.yaml");
  solver::Solver a(model);
  for (int k = 0; k < 5; ++k) a.step();
  a.delete_elements({2});
  a.step();
  std::stringstream file;
  StateWriter writer(file);
  a.visit_state(writer);
  solver::Solver b(model);
  StateReader reader(file, "bar.state");
  b.visit_state(reader);
  for (int k = 0; k < 20; ++k) a.step(), b.step();
  EXPECT_EQ(a.state().x, b.state().x);
  EXPECT_EQ(a.state().v, b.state().v);
  EXPECT_EQ(b.state().removed_node_count(), 4);
  EXPECT_EQ(a.balance().total(), b.balance().total());
  for (std::size_t i = 0; i < model.num_nodes(); ++i)
    if (b.state().removed_nodes[i]) EXPECT_EQ(b.state().v[3 * i + 2], 0.0);
}

}  // namespace
}  // namespace plyimpact
