// Whether a loop of the contact's set-up or search over `items` independent items runs on all
// threads: below 2048 items one thread is faster, as a parallel region costs a few microseconds.
// Every such loop writes per item or reduces with min / max, so its result does not depend on the
// thread count.
#pragma once

#include <cstddef>

#include <omp.h>

namespace plyimpact::contact {

inline constexpr std::size_t kParallelMinItems = 2048;

inline bool parallel_items(std::size_t items) { return items >= kParallelMinItems && omp_get_max_threads() > 1; }

}  // namespace plyimpact::contact
