// Static split of a loop over threads, in our hands rather than OpenMP's schedule(static), so that
// different passes give a thread the same items (and the same nodes' cache lines).
#pragma once

#include <cstdint>

namespace plyimpact::solver {

// The items [begin, end) of thread t of nt when n items are split into contiguous, nearly equal
// ranges in thread order: the element pass's chunks, the rigid bodies' placed nodes.
struct ThreadRange {
  long begin = 0, end = 0;
};
inline ThreadRange thread_range(long n, int t, int nt) {
  return {long(std::int64_t(n) * t / nt), long(std::int64_t(n) * (t + 1) / nt)};
}

}  // namespace plyimpact::solver
