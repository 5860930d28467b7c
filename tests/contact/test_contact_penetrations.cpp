// Penetrations (PenaltyContact::penetrations, run/run_checks ContactPenetrationCheck): a node
// released while still behind the face it was in contact with has passed through the surface, and
// the run must say so (LS-DYNA reports the penetrations it releases).
//  - A heavy rigid (MAT_020) punch, 1 mm cube of density 160000 (2.0e-3 J at 50 m/s, a hundred
//    times what its springs hold at the release depth), fired onto a soft block (E = 100 MPa, SOFT
//    0 with its default SLSFAC, k ~ SLSFAC K h ~ 8e3 N/m per node). The springs cannot stop it:
//    its bottom nodes pass the release depth (0.4 h = 0.4 mm) while over the block's face and are
//    released there. Reference: the geometry of the release: each recorded node lies behind the
//    face of its last segment (depth > 0), at the time of a pass of the run; the live line and the
//    warning name the contact, the node (1-based) and the depth in mm.
//  - The head-on steel blocks (test_penalty_contact) bounce: no node is released behind a face,
//    count 0 (the criterion does not flag a normal separation).
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

#include "head_on_blocks.hpp"
#include "run/run_checks.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

std::string through_scene() {
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
         "materials:\n  soft: {card: MAT_001, RO: 1000, E: 1.0e8, PR: 0.3}\n"
         "  tup: {card: MAT_020, RO: 160000, E: 210e9, PR: 0.3}\n"
         "sections:\n  s: {ELFORM: 2}\n"
         "parts:\n  block: {material: soft, section: s}\n  tup: {material: tup, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: block, origin: [-0.002, -0.002, -0.001], size: [0.005, 0.005, 0.001], elements: [5, 5, 1]}\n"
         "    - {part: tup, origin: [0, 0, 0.00005], size: [0.001, 0.001, 0.001], elements: [1, 1, 1]}\n"
         "initial_velocity:\n  - {part: tup, velocity: [0, 0, -50]}\n"
         "contacts:\n  - {name: target, type: automatic_surface_to_surface, surfaces: [tup, block], SOFT: 0}\n";
}

TEST(ContactPenetrations, PunchThroughASoftBlockIsReportedWithNodeTimeAndDepth) {
  const model::Model model = test::model_from_yaml(through_scene(), "through.yaml");
  solver::Solver solver(model);
  std::ostringstream live;
  run::ContactPenetrationCheck check(&live);
  double t_first_pass = -1;
  while (solver.state().time < 100e-6) {
    solver.step();
    check.after_cycle(solver);
    if (t_first_pass < 0) t_first_pass = solver.state().time;
  }
  const auto& p = solver.contacts()[0].penetrations();
  std::cout << "punch through: " << p.count << " penetrations, first node " << p.first.node << " at " << p.first.time
            << " s, " << p.first.depth << " m deep; deepest " << p.deepest.depth << " m\n" << live.str();
  ASSERT_GT(p.count, 0);
  EXPECT_GT(p.first.depth, 0.0);
  EXPECT_GE(p.deepest.depth, p.first.depth);
  EXPECT_GE(p.first.time, t_first_pass);
  EXPECT_LE(p.last.time, solver.state().time);
  EXPECT_NE(live.str().find("contact 'target'"), std::string::npos);
  run::RunReport report;
  check.stop(&solver, report);
  ASSERT_EQ(report.warnings.size(), 1u);
  std::cout << report.warnings[0] << "\n";
  EXPECT_NE(report.warnings[0].find("penetration"), std::string::npos);
  EXPECT_NE(report.warnings[0].find("node " + std::to_string(long(p.first.node) + 1)), std::string::npos);
  EXPECT_NE(report.warnings[0].find("mm deep"), std::string::npos);
}

TEST(ContactPenetrations, BlocksThatBounceReportNone) {
  const model::Model model = test::model_from_yaml(test::head_on_blocks("SOFT: 0"), "head_on.yaml");
  solver::Solver solver(model);
  long cycles_in_contact = 0;
  while (solver.state().time < 3 * 43e-6) {
    solver.step();
    if (solver.contacts()[0].forces().active > 0) ++cycles_in_contact;
  }
  ASSERT_GT(cycles_in_contact, 0);
  EXPECT_EQ(solver.contacts()[0].penetrations().count, 0);
}

}  // namespace
}  // namespace plyimpact
