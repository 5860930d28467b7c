// Rigid bodies (*MAT_020, solver/rigid_body): torque-free motion of an asymmetric body spinning
// about a non-principal axis keeps its angular momentum vector exactly (H only changes by applied
// moments; |H| to 1e-12 relative) and its kinetic energy to 1e-3 (the explicit rotation update is
// not exactly energy conserving; the error is O(omega dt)^2 per revolution, ~1e-4 here); the centre
// of mass moves at constant velocity (to round-off); CON1/CON2 fix translations/rotations; a
// prescribed velocity is followed exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/error.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

std::string scene(const std::string& card_extra, const std::string& extra) {
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
         "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
         "  rig: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3" + card_extra + "}\n"
         "sections:\n  s: {ELFORM: 2}\n"
         "parts:\n  body: {material: rig, section: s}\n  other: {material: steel, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: body, origin: [0, 0, 0], size: [0.01, 0.02, 0.03], elements: [1, 2, 3]}\n"
         "    - {part: other, origin: [1, 1, 1], size: [0.01, 0.01, 0.01], elements: [2, 2, 2]}\n"
         "node_sets:\n  body_nodes: {part: body}\n" + extra;
}

TEST(RigidBody, TorqueFreeSpinKeepsAngularMomentum) {
  model::Model model = test::model_from_yaml(scene("", ""), "spin.yaml");
  ASSERT_EQ(model.rigid_bodies.size(), 1u);
  // Spin about a non-principal axis plus a drift: set the initial motion directly.
  auto& body = model.rigid_bodies[0];
  body.velocity = {1.0, -2.0, 0.5};
  body.angular_velocity = {300.0, 200.0, -100.0};
  solver::Solver solver(model);
  const auto h0 = solver.rigid_bodies()[0].h;
  const double ke0 = solver.balance().kinetic();
  const auto x0 = solver.rigid_bodies()[0].x;
  double max_h = 0;
  while (solver.state().time < 0.02) {  // ~1 revolution at |omega| = 374 rad/s
    solver.step();
    const auto& h = solver.rigid_bodies()[0].h;
    for (int d = 0; d < 3; ++d) max_h = std::max(max_h, std::abs(h[d] - h0[d]));
  }
  const double hn = std::hypot(h0[0], h0[1], h0[2]);
  const auto& s = solver.rigid_bodies()[0];
  const double t = solver.state().time;
  std::cout << "spin: max |H - H0| / |H0| " << max_h / hn << ", KE " << solver.balance().kinetic() << " vs " << ke0
            << "\n";
  EXPECT_LT(max_h / hn, 1e-12);
  EXPECT_NEAR(solver.balance().kinetic(), ke0, 1e-3 * ke0);
  EXPECT_NEAR(s.x[0], x0[0] + 1.0 * t, 1e-12);
  EXPECT_NEAR(s.x[1], x0[1] - 2.0 * t, 1e-12);
  // Slaved nodes keep their distances (rigidity): first and last node of the body.
  const auto& nodes = model.rigid_bodies[0].nodes;
  auto dist = [&](const std::vector<double>& x, Index a, Index b) {
    return std::hypot(x[3 * a] - x[3 * b], x[3 * a + 1] - x[3 * b + 1], x[3 * a + 2] - x[3 * b + 2]);
  };
  EXPECT_NEAR(dist(solver.state().x, nodes.front(), nodes.back()), dist(model.X, nodes.front(), nodes.back()), 1e-12);
}

TEST(RigidBody, CardConstraintsAndPrescribedVelocity) {
  // CON1 = 4 (x and y fixed), CON2 = 7 (no rotation); z prescribed at 3 m/s; gravity acts along x.
  const model::Model model = test::model_from_yaml(
      scene(", CMO: 1, CON1: 4, CON2: 7",
            "gravity: [9.81, 0, 0]\nrigid_bodies:\n  - {part: body, velocity: {dofs: [z], value: 3}}\n"),
      "constrained.yaml");
  solver::Solver solver(model);
  const auto x0 = solver.rigid_bodies()[0].x;
  test::run_until(solver, 1e-3);
  const auto& s = solver.rigid_bodies()[0];
  EXPECT_NEAR(s.x[0], x0[0], 1e-15);
  EXPECT_NEAR(s.x[1], x0[1], 1e-15);
  EXPECT_NEAR(s.x[2], x0[2] + 3e-3, 1e-12);
  EXPECT_EQ(s.omega[0], 0.0);
}

TEST(RigidBody, BadInputIsRefused) {
  EXPECT_THROW(test::model_from_yaml(scene(", CON1: 4", ""), "bad.yaml"), InputError);  // CON1 without CMO
  EXPECT_THROW(test::model_from_yaml(scene("", "boundary_conditions:\n  - {node_set: body_nodes, fix: [x]}\n"),
                                     "bad2.yaml"),
               InputError);
  EXPECT_THROW(test::model_from_yaml(scene("", "rigid_bodies:\n  - {part: other}\n"), "bad3.yaml"), InputError);
}

}  // namespace
}  // namespace plyimpact
