// The bucket-sort interval BSORT is a cost knob, not a physics one: each sort lists for every contact
// node all segments it can reach before the next sort (SegmentSearch), so a contact sorted every
// cycle (BSORT 1), every 10 cycles, or only when the motion requires it (BSORT 0, the default)
// finds the same springs and gives the same forces. Reference: the run sorted every cycle, which
// searches from fresh lists at each pass. The comparison is exact (bytes of every figure the
// contact reports but its sort count, every cycle): the candidate lists differ in length only,
// and the nearest-segment choice does not depend on how many far segments a list holds.
// Scene: head_on_blocks pressed together while sliding (friction, viscous damping), with an
// eroding rebuild half-way (free_nodes.hpp), as in the restart test.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "free_nodes.hpp"
#include "head_on_blocks.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

struct SortedRun {
  std::vector<std::vector<char>> figures;  // per cycle
  long sorts = 0;
  long active_max = 0;
};

SortedRun run_with(const std::string& bsort) {
  const model::Model model = test::model_from_yaml(
      test::head_on_blocks("SOFT: 1, FS: 0.3, FD: 0.2, DC: 10, VDC: 20, BSORT: " + bsort), "sort_interval.yaml");
  test::FreeNodes r = test::pressed_sliding_blocks(model);
  contact::PenaltyContact pc(model, model.contacts[0], r.x, 1e-8);
  r.dt = 0.3 * pc.stable_step();
  SortedRun out;
  for (int c = 0; c < 750; ++c) {
    if (c == 300) test::erode_under_block_b(model, pc, r.x);
    test::contact_cycle(model, pc, r);
    out.figures.push_back(test::contact_figures(pc, r, /*with_sorts=*/false));
    out.active_max = std::max(out.active_max, long(pc.forces().active));
  }
  out.sorts = pc.sorts();
  return out;
}

TEST(ContactSortInterval, EveryIntervalFindsTheSameSpringsAsSortingEveryCycle) {
  const SortedRun every = run_with("1"), ten = run_with("10"), automatic = run_with("0");
  ASSERT_GT(every.active_max, 0) << "no contact formed";
  for (const SortedRun* other : {&ten, &automatic}) {
    SCOPED_TRACE(other == &ten ? "BSORT 10" : "BSORT 0");
    for (std::size_t c = 0; c < every.figures.size(); ++c)
      ASSERT_EQ(other->figures[c], every.figures[c]) << "first difference at cycle " << c;
  }
  std::printf("sorts in 750 cycles: BSORT 1 %ld, BSORT 10 %ld, BSORT 0 %ld\n", every.sorts, ten.sorts, automatic.sorts);
  EXPECT_EQ(every.sorts, 750 + 2);  // one per pass, and the sorts of construction and of the rebuild
  EXPECT_LT(ten.sorts, every.sorts);
  EXPECT_LT(automatic.sorts, ten.sorts);  // on motion and at the rebuild only
  EXPECT_GE(automatic.sorts, 2);
}

}  // namespace
}  // namespace plyimpact
