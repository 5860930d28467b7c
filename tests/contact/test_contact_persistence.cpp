// A node in contact stays in contact (contact/penalty_contact, find_segment and build): the search
// catches a node that was not in contact only within the depth it can have crossed in one step
// (else a node beside an edge would be shot through a side face), so two things must keep the
// full release depth for a node already pressed into a surface:
//  - Sliding: a block pressed into a plate slides across the plate's segment boundaries; the
//    neighbour segment it slides onto is not a new contact. Reference: statics, the mean contact
//    force on the block equals its weight m g (frictionless, so the sliding does not change it),
//    and the block does not sink: its height stays at the settled value (the penalty springs carry
//    the same load at every position). With the one-step catch depth alone every node would be
//    released at the first boundary it crosses (the penetration, ~0.1 mm here, is deeper than the
//    one-step depth, 2 dt (v + v_max) + 2 % of the release depth, ~ 0.06 mm) and the block would
//    fall through the plate.
//  - Erosion elsewhere: the eroding contact rebuilds its surfaces (new segment numbers); a node
//    pressed into a surviving segment keeps its spring. Reference: the same state before and after
//    the rebuild gives the same force (nothing about the pressed nodes changed).
// The load is a body force of 1e4 m/s^2 and the penalty is softened (SFS = SFM = 1e-4) so that the
// static penetration (~ 0.1 mm, m g / (9 k)) is well beyond the one-step depth; VDC 20 damps the
// settling oscillation of the block on its springs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kGravity = 1e4;  // m/s^2

std::string scene(bool sliding) {
  const std::string base =
      sliding ? "  plate: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3, CMO: 1, CON1: 7, CON2: 7}\n"
              : "  plate: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n";
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
         "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n" + base +
         "sections:\n  s: {ELFORM: 2}\n"
         "parts:\n  block: {material: steel, section: s}\n  plate: {material: plate, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: plate, origin: [-0.01, -0.01, -0.002], size: [0.1, 0.03, 0.002], elements: [20, 1, 1]}\n"
         "    - {part: block, origin: [0, 0, 0], size: [0.01, 0.01, 0.01], elements: [2, 2, 2]}\n" +
         (sliding ? "initial_velocity:\n  - {part: block, velocity: [1, 0, 0]}\n"
                  : "node_sets:\n  bottom: {plane: {axis: z, value: -0.002}}\n"
                    "boundary_conditions:\n  - {node_set: bottom, fix: [x, y, z]}\n") +
         "gravity: [0, 0, -1e4]\n"
         "contacts:\n  - {name: press, type: " +
         (sliding ? "automatic" : "eroding") +
         "_surface_to_surface, surfaces: [block, plate], SOFT: 0, SFS: 4e-4, SFM: 4e-4, PENMAX: 0.001, VDC: 20}\n";
}

const model::ElementBlock& part_block(const model::Model& m, const std::string& part) {
  for (const auto& b : m.blocks)
    if (m.parts[std::size_t(b.part)].name == part) return b;
  throw std::runtime_error("no part " + part);
}

double block_mass(const model::Model& m) { return m.materials[part_block(m, "block").material].density * 1e-6; }

double block_z(const model::Model& m, const solver::Solver& s) {
  const model::ElementBlock& blk = part_block(m, "block");
  double z = 0, mass = 0;
  for (std::size_t i = 0; i < m.num_nodes(); ++i)
    if (std::find(blk.conn.begin(), blk.conn.end(), Index(i)) != blk.conn.end()) {
      z += m.mass[i] * s.state().x[3 * i + 2];
      mass += m.mass[i];
    }
  return z / mass;
}

TEST(ContactPersistence, PressedBlockSlidesAcrossSegmentBoundariesWithoutSinking) {
  const model::Model model = test::model_from_yaml(scene(true), "slide.yaml");
  solver::Solver solver(model);
  const double weight = block_mass(model) * kGravity;
  // Settle for 5 ms (VDC 20: the block's bounce on its springs, period ~ 0.6 ms, decays in ~ 3 ms)
  // while sliding within the first plate segment (x in [0, 5 mm) at 1 m/s), then slide for 20 ms:
  // the block's nodes cross four segment boundaries each.
  test::run_until(solver, 5e-3);
  const double z_settled = block_z(model, solver);
  double force_sum = 0, max_sink = 0;
  long samples = 0;
  while (solver.state().time < 25e-3) {
    solver.step();
    force_sum += solver.contacts()[0].forces().resultant[2];
    ++samples;
    max_sink = std::max(max_sink, z_settled - block_z(model, solver));
  }
  const double z0 = 0.005;  // centre of the block resting on the undeformed plate
  const double penetration = z0 - z_settled;
  std::cout << "sliding: mean contact force " << force_sum / double(samples) << " N (weight " << weight
            << " N), settled penetration " << penetration * 1e6 << " um, deepest further sinking "
            << max_sink * 1e6 << " um, energy ratio " << solver.energy_ratio() << "\n";
  // The mean force over 20 ms (~ 30 periods of the residual bounce) against the weight: 2 %.
  EXPECT_NEAR(force_sum / double(samples), weight, 0.02 * weight);
  // The penetration must be deeper than the one-step catch depth for the test to mean anything.
  EXPECT_GT(penetration, 50e-6);
  // No sinking beyond the residual bounce: 10 % of the settled penetration.
  EXPECT_LT(max_sink, 0.1 * penetration);
}

TEST(ContactPersistence, RebuildAfterErosionElsewhereKeepsThePressedSprings) {
  const model::Model model = test::model_from_yaml(scene(false), "press.yaml");
  solver::Solver solver(model);
  const double weight = block_mass(model) * kGravity;
  test::run_until(solver, 10e-3);  // settled
  const double before = solver.contacts()[0].forces().resultant[2];
  // The plate's last element (x = 85-90 mm), far from the block (x = 0-10 mm).
  solver.delete_elements({part_block(model, "plate").element_id.back()});
  solver.step();
  const double after = solver.contacts()[0].forces().resultant[2];
  std::cout << "rebuild: contact force before " << before << " N, after " << after << " N (weight " << weight
            << " N), segments " << solver.contacts()[0].num_segments() << "\n";
  // Settled: the force carries the weight (VDC 20 over 10 ms, ~ 16 periods: within 2 %).
  EXPECT_NEAR(before, weight, 0.02 * weight);
  // One step later the state has barely moved: the same force to 1e-3 (a step changes the
  // penetration by v dt, ~ 1e-9 m against 1e-4 m).
  EXPECT_NEAR(after, before, 1e-3 * std::abs(before));
}

}  // namespace
}  // namespace plyimpact
