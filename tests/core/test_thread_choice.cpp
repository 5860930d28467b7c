// The automatic thread count (solver/thread_choice.hpp) decides on the median cycle of each probe
// window, leaving out the first cycle after a switch. Synthetic cycle times stand in for the
// clock: all threads take 0.6 of one thread's cycle, as the default scene does on two cores. One
// slow cycle in the all-threads window (an erosion rebuild, a sort, a thread count just switched
// to) must not make it pick one thread; all threads slower in most cycles must.
#include <gtest/gtest.h>
#include <omp.h>

#include <functional>

#include "solver/thread_choice.hpp"

namespace plyimpact {
namespace {

using solver::ThreadChoice;

// Runs one probe (from its first cycle) with cycle times from `time(threads, k)`, k the cycle's
// index in its window (0 = the cycle right after the switch); returns the choice.
int probe(const std::function<double(int, int)>& time) {
  omp_set_num_threads(2);
  ThreadChoice choice;
  choice.enable(true);
  long cycle = 0;
  for (int window = 0; window < 2; ++window)
    for (int k = 0; k <= ThreadChoice::kProbe; ++k, ++cycle) {
      choice.before_cycle(cycle);
      choice.after_cycle(cycle, time(omp_get_max_threads(), k));
    }
  omp_set_num_threads(2);
  return choice.chosen();
}

TEST(ThreadChoice, KeepsAllThreadsThatAreFasterInMostCycles) {
  EXPECT_EQ(probe([](int threads, int) { return threads == 1 ? 1e-3 : 0.6e-3; }), 2);
}

TEST(ThreadChoice, OneSlowCycleDoesNotDecide) {
  // A rebuild in the all-threads window costs 20 ordinary cycles: its sum (29 against 16 ms)
  // would pick one thread; its median does not.
  EXPECT_EQ(probe([](int threads, int k) { return threads == 1 ? 1e-3 : k == 5 ? 20e-3 : 0.6e-3; }), 2);
  // Nor does the switch: the first all-threads cycle at 30 ordinary ones.
  EXPECT_EQ(probe([](int threads, int k) { return threads == 1 ? 1e-3 : k == 0 ? 30e-3 : 0.6e-3; }), 2);
}

TEST(ThreadChoice, PicksOneThreadWhenAllAreSlower) {
  // An oversubscribed machine: every synchronisation waits for a time slice.
  EXPECT_EQ(probe([](int threads, int) { return threads == 1 ? 1e-3 : 3e-3; }), 1);
  // Not clearly faster (0.95 of one thread, the gain asked for is 0.9).
  EXPECT_EQ(probe([](int threads, int) { return threads == 1 ? 1e-3 : 0.95e-3; }), 1);
}

}  // namespace
}  // namespace plyimpact
