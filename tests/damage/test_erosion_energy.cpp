// Energy at an erosion hole's edge: a body that has dropped into the hole an element's erosion left
// and slides towards its rim must not gain energy there.
//
// Mechanism (default scene: the energy ratio stepped from 1.00002 to 1.019 at 1.4 ms with IHQ 2,
// to 1.10 with IHQ 6, in steps at the erosion bursts; measured by booking every element's and the
// contact's work exactly): after a burst the tup's nodes sit inside the holes, a little below the
// plane of the surrounding ply faces. A node that slides sideways under the edge of such a face
// (within the projection tolerance MAXPAR) is, from one step to the next, "behind" that face by its
// depth below the face plane without having crossed the face. The contact catches a new contact
// down to its catch depth (one step's relative motion, bounded with the fastest contact node, plus
// 2 % of the release depth: 20 um and more once orphan nodes of eroded elements fly off), and it
// took such a node with a spring of that whole depth: 0.5 k g^2 created in one step (0.05-0.1 J per
// node at the tup's penalty stiffness), booked as contact energy and so invisible there, released
// into the plate as the spring pushed the node out and dissipated mostly by the hourglass
// viscosity of the live elements around the hole, where the gain was seen.
//
// Scene: the steel punch-on-base scene (tests/contact/punch_on_base.hpp), the base's top middle
// element deleted as by erosion (a 1 mm hole, eroding contact rebuilt), and a punch of 0.8 x 0.8 x
// 0.5 mm above the hole, moving at 10 m/s towards the hole's wall and 1 m/s down: it sinks into the
// hole while it slides, so its leading bottom nodes reach the rim a few um below the plane of the
// base's top face (caught by that face's MAXPAR margin ~12 um before they reach the wall).
// Reference: conservation of energy (elastic bodies, ELFORM 2 without hourglass modes, frictionless
// contact; bulk viscosity and contact work booked), so the energy ratio stays at 1. Tolerance 1 %:
// every spring that acts here is booked by the trapezoid rule, whose error is a fraction of the
// potential the springs hold, and that stays below 0.5 % of the punch's kinetic energy when no
// spring is taken from nothing; one taken at the 4 um depth holds about half of it (measured
// without the fix: energy ratio 1.72).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "../contact/punch_on_base.hpp"
#include "../core/support.hpp"

namespace plyimpact {
namespace {

TEST(ErosionEnergy, BodySlidingIntoAnErodedHolesRimCreatesNoEnergy) {
  // Punch: x 1.15..1.95 mm (its leading face 50 um from the hole's wall at x = 2 mm), y 1.1..1.9
  // mm, bottom 1 um above the base's top face (z = 2 mm): no initial penetration with the element
  // still in place. At 10 m/s it reaches the wall in 5 us, having sunk 4 um below the rim.
  std::string yaml = test::punch_on_base("[0.00115, 0.0011, 0.002001]", "[0.0008, 0.0008, 0.0005]", "[2, 2, 1]",
                                         "[10, 0, -1]", "eroding_surface_to_surface");
  const std::string ctl = "control: {termination_time: 1.0}";
  yaml.replace(yaml.find(ctl), ctl.size(), "control: {termination_time: 1.0, energy_ratio_limit: 0}");
  const model::Model model = test::model_from_yaml(yaml, "hole_rim.yaml");
  solver::Solver solver(model);
  ASSERT_EQ(solver.initial_penetrations()[0].count, 0u);
  solver.delete_elements({14});  // top middle element (ids: base first, x fastest; top layer 10..18)
  const double ke0 = solver.balance().kinetic();
  double ratio_max = 1, ratio_min = 1, potential_max = 0;
  long contact_cycles = 0;
  while (solver.state().time < 15e-6) {  // the punch reaches the wall at 5 us and bounces back
    solver.step();
    ratio_max = std::max(ratio_max, solver.energy_ratio());
    ratio_min = std::min(ratio_min, solver.energy_ratio());
    potential_max = std::max(potential_max, solver.contacts()[0].forces().potential);
    if (solver.contacts()[0].forces().active > 0) ++contact_cycles;
  }
  std::cout << "hole rim: initial KE " << ke0 << " J, largest spring potential " << potential_max
            << " J, energy ratio " << ratio_min << " .. " << ratio_max << ", cycles in contact " << contact_cycles
            << ", punch vx at the end " << solver.state().v[3 * (model.num_nodes() - 1)] << " m/s\n";
  ASSERT_GT(contact_cycles, 0);  // the punch did reach the rim
  EXPECT_LT(ratio_max, 1.01);
  EXPECT_GT(ratio_min, 0.99);
}

}  // namespace
}  // namespace plyimpact
