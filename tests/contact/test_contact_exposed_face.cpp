// A face that erosion exposes already behind a node (contact/penalty_contact, apply): nothing
// crossed anything, so no spring may appear with the depth found there. When plies erode under an
// impactor, the rebuilt surface has new faces, and an impactor node already tens of um behind one
// of them would, taken as a new contact, get a spring nobody compressed (energy from nowhere in
// one step). Such penetrations are kept as offsets, like initial penetrations: the force starts
// from zero and grows with further penetration.
//
// Scene: a steel base (3 x 3 x 2 elements of 1 mm) and a small steel punch inside its top middle
// element, 0.9 mm wide in x and reaching 5 um past the element's -x face, moving at 1 m/s towards
// +x. Deleting the element (eroding contact, rebuilt) exposes the side faces of its neighbours: the
// punch's -x nodes lie 5 um behind one. The punch backs out of it (the offset relaxes and ends),
// crosses the slot and bounces off the other side. Bulk viscosity off: after the bounce the free
// punch vibrates, and at TSSFAC 0.9 the bulk-viscosity term of the time step pumps energy into a
// free vibration (+2.5 % in 40 us here; README, "Bulk viscosity"), which is not what this test is
// about. Reference: conservation of energy (elastic bodies, ELFORM 2, frictionless, no damping):
// KE + IE + contact energy stays at the punch's initial KE up to the discretisation of the contact
// pulse (it must shrink with the step: see the test), the punch's x velocity reverses (it
// bounced) and the contact never gives the bodies more than 1 % of the KE beyond what they gave it
// (taken - held, PenaltyContact::created; the same discretisation error). Without the
// offsets the 5 um springs stop the run at cycle 3 with an energy ratio of 419.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "punch_on_base.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

std::string exposed_scene(const std::string& tssfac) {
  std::string yaml = test::punch_on_base("[0.000995, 0.0011, 0.0012]", "[0.0009, 0.0008, 0.0005]", "[2, 2, 1]",
                                         "[1, 0, 0]", "eroding_surface_to_surface", "{ELFORM: 2, Q1: 0, Q2: 0}");
  const std::string ctl = "control: {termination_time: 1.0}";
  yaml.replace(yaml.find(ctl), ctl.size(), "control: {termination_time: 1.0, tssfac: " + tssfac + "}");
  return yaml;
}

double punch_vx(const model::Model& m, const solver::Solver& s) {
  double p = 0, mass = 0;
  for (const auto& blk : m.blocks)
    if (m.parts[std::size_t(blk.part)].name == "punch")
      for (Index n : blk.conn) {  // nodes counted once per element: a weighted mean, fine for a sign
        p += m.mass[n] * s.state().v[3 * std::size_t(n)];
        mass += m.mass[n];
      }
  return p / mass;
}

struct Outcome {
  long offsets = 0;
  double e_min = 0, ratio_err = 0, peak = 0, vx_min = 1, initial = 0;
};

Outcome push(const std::string& tssfac) {
  const model::Model model = test::model_from_yaml(exposed_scene(tssfac), "exposed.yaml");
  solver::Solver solver(model);
  EXPECT_EQ(solver.initial_penetrations()[0].count, 0u);  // the wall is an inner face at t = 0
  solver.delete_elements({14});  // top middle element (ids: base first, x fastest; top layer 10..18)
  Outcome o;
  while (solver.state().time < 150e-6) {  // reaches the +x wall after ~105 us and bounces
    solver.step();
    o.e_min = std::min(o.e_min, -solver.contacts()[0].created());
    o.ratio_err = std::max(o.ratio_err, std::abs(solver.energy_ratio() - 1));
    o.peak = std::max(o.peak, solver.contacts()[0].forces().normal);
    o.vx_min = std::min(o.vx_min, punch_vx(model, solver));
  }
  o.offsets = solver.contacts()[0].exposed_offsets();
  o.initial = solver.state().initial_total_energy;
  std::cout << "exposed face, TSSFAC " << tssfac << ": offsets " << o.offsets << ", max |ratio - 1| " << o.ratio_err
            << ", contact's taken - held min " << o.e_min << " J, peak normal force " << o.peak << " N, punch vx min "
            << o.vx_min << " m/s (was 1)\n";
  return o;
}

// Energy: the error of the run at the default TSSFAC 0.9 (0.93 %) is the discretisation of the
// contact pulse, not a spring from nowhere: it must shrink when the step is halved, by more than
// 2x (measured 2.4x; the SOFT 1 stiffness follows the step, so the order is not a clean 2), and
// at TSSFAC 0.45 stay within the head-on test's 1 % by a wide margin (measured 0.38 %). A 5 um
// spring from nowhere would not shrink with the step (its energy is 0.5 k (5 um)^2 at any step).
TEST(ExposedFace, NodeAlreadyBehindAFaceErosionExposesGetsAnOffsetNotASpring) {
  const Outcome o = push("0.9"), half = push("0.45");
  EXPECT_GT(o.offsets, 0);
  EXPECT_LT(half.ratio_err, 0.5 * o.ratio_err);
  EXPECT_LT(half.ratio_err, 0.01);
  EXPECT_GE(o.e_min, -1e-2 * o.initial);
  EXPECT_GT(o.peak, 0.0);  // it did push: the offset is a baseline, not a release
  EXPECT_LT(o.vx_min, -0.5);  // bounced off the +x wall (elastic: back at nearly -1 m/s)
}

}  // namespace
}  // namespace plyimpact
