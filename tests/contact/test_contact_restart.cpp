// Restart of a penalty contact (PenaltyContact::visit_state): a contact run for N cycles, its state
// copied through a visitor into a second contact freshly built from the same model and definition,
// continues exactly like the first for the next M cycles. Reference: the uninterrupted run itself;
// the comparison is exact (bit-identical forces, energies, pass figures), since the restart is
// meant to be invisible. The scene exercises every piece of run state: two blocks pressed together
// with SOFT 1, friction (FS, FD, DC) and viscous damping (VDC), so springs, friction forces and
// both energies build up; an element of the lower block deleted half-way (the eroding rebuild: a
// segment set of another size, remapped springs, exposure offsets); sorts by interval and motion.
// Nodes move as free lumped masses under the contact forces alone (free_nodes.hpp).
// A control run (no state copied) must differ, so that the test cannot pass by the second contact
// simply repeating the first from the same arrays.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "free_nodes.hpp"
#include "head_on_blocks.hpp"
#include "state_copy.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

TEST(ContactRestart, StateCopiedThroughAVisitorContinuesBitIdentically) {
  const model::Model model =
      test::model_from_yaml(test::head_on_blocks("SOFT: 1, FS: 0.3, FD: 0.2, DC: 10, VDC: 20, BSORT: 10"), "restart.yaml");
  const model::Contact& def = model.contacts[0];
  test::FreeNodes run = test::pressed_sliding_blocks(model);
  const std::vector<double> x_start = run.x;

  contact::PenaltyContact first(model, def, x_start, 1e-8);
  run.dt = 0.3 * first.stable_step();
  const int kBefore = 450, kErode = 300, kAfter = 300;
  long active_max = 0;
  for (int c = 0; c < kBefore; ++c) {
    if (c == kErode) test::erode_under_block_b(model, first, run.x);
    test::contact_cycle(model, first, run);
    active_max = std::max(active_max, long(first.forces().active));
  }
  // The scene did what it is for.
  ASSERT_GT(active_max, 0) << "no contact formed";
  ASSERT_GT(first.friction_energy(), 0.0);
  contact::PenaltyContact fresh(model, def, x_start, 1e-8);
  ASSERT_NE(fresh.num_segments(), first.num_segments()) << "the rebuild did not change the segment set";

  test::StateRecorder recorder;
  first.visit_state(recorder);
  test::StateReplayer replayer(recorder.blocks);
  fresh.visit_state(replayer);
  ASSERT_EQ(replayer.replayed(), recorder.blocks.size());
  contact::PenaltyContact control(model, def, x_start, 1e-8);  // same arrays, no state

  test::FreeNodes second = run, third = run;
  long active = 0;
  for (int c = 0; c < kAfter; ++c) {
    test::contact_cycle(model, first, run);
    test::contact_cycle(model, fresh, second);
    ASSERT_EQ(test::contact_figures(first, run, true), test::contact_figures(fresh, second, true))
        << "cycle " << kBefore + c << " after the restart";
    active += long(first.forces().active);
    if (c == 0) {
      test::contact_cycle(model, control, third);
      EXPECT_NE(test::contact_figures(first, run, true), test::contact_figures(control, third, true))
          << "the control run without state agrees";
    }
  }
  EXPECT_GT(active, 0) << "no spring active after the restart";
  EXPECT_EQ(run.x, second.x);
  EXPECT_EQ(run.v, second.v);
}

}  // namespace
}  // namespace plyimpact
