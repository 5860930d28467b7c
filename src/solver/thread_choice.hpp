// How many threads the cycle runs on when the user did not fix it (control.threads 0): measured,
// not guessed. Every kInterval cycles the cycle runs kProbe cycles on one thread and kProbe on all,
// and keeps all only when their median cycle was clearly faster. Why: on an idle machine two threads pay off
// from ~10^3 elements, but on an oversubscribed one every synchronisation point of a cycle can wait
// a scheduler time slice for a thread that is not running (measured: a 1600-element laminate
// impact took 30 s on two threads against 3 s on one at a load average of 18). The results are
// bit-identical for any thread count, so switching changes nothing but the wall time.
//   Medians, not sums, and the first cycle after a switch left out: a cycle that erodes (the
// contact rebuild is serial) or re-sorts costs several ordinary ones, and a thread count just
// switched to starts with cold caches; either, falling in one window, made the sums pick one
// thread for the next kInterval cycles of the default scene (its whole event took 126 s against 79 s
// with two threads fixed).
#pragma once

#include <algorithm>

#include <omp.h>

namespace plyimpact::solver {

class ThreadChoice {
 public:
  static constexpr long kInterval = 4000;  // cycles between probes
  static constexpr int kProbe = 16;        // cycles per thread count in a probe
  static constexpr double kGain = 0.9;     // all threads kept when they take below this share of one

  // Off: the OpenMP thread count is left as it is. On: probes start at the next cycle.
  void enable(bool on) {
    enabled_ = on;
    max_threads_ = omp_get_max_threads();
    next_probe_ = 0;
  }
  bool enabled() const { return enabled_ && max_threads_ > 1; }

  // Before a cycle (cycle number): sets the thread count of the cycle.
  void before_cycle(long cycle) {
    if (!enabled()) return;
    if (probing_ == 0 && cycle >= next_probe_) {
      probing_ = 1;
      probe_cycles_ = 0;
    }
    const int want = probing_ == 1 ? 1 : probing_ == 2 ? max_threads_ : chosen_;
    if (want != omp_get_max_threads()) omp_set_num_threads(want);
  }
  // After it, with its wall time.
  void after_cycle(long cycle, double seconds) {
    if (!enabled() || probing_ == 0) return;
    if (probe_cycles_ > 0) times_[probing_ - 1][probe_cycles_ - 1] = seconds;  // the first: the switch
    if (++probe_cycles_ < kProbe + 1) return;
    probe_cycles_ = 0;
    if (probing_ == 1) {
      probing_ = 2;
      return;
    }
    probing_ = 0;
    chosen_ = median(times_[1]) < kGain * median(times_[0]) ? max_threads_ : 1;
    next_probe_ = cycle + kInterval;
  }
  int chosen() const { return chosen_; }

 private:
  bool enabled_ = false;
  int max_threads_ = 1, chosen_ = 1;
  int probing_ = 0;  // 0 none, 1 timing one thread, 2 timing all
  int probe_cycles_ = 0;
  long next_probe_ = 0;
  double times_[2][kProbe] = {};  // per probed cycle, one thread and all

  static double median(double (&t)[kProbe]) {
    std::nth_element(t, t + kProbe / 2, t + kProbe);
    return t[kProbe / 2];
  }
};

}  // namespace plyimpact::solver
