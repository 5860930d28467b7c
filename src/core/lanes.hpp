// Lane layout of the one-point element pass: elements are processed kLanes at a time, every
// per-element quantity is an array over the lanes (a[component][lane]) and every statement a loop
// over them, which the compiler turns into SIMD instructions (8 doubles fill an AVX-512 register).
// The arithmetic of a lane is exactly that of a one-element-at-a-time loop.
//
// What GCC's `omp simd` vectorises reliably (checked with -fopt-info-vec): straight-line bodies
// over per-lane scalars, no `bool` lanes, no closures in the loop body, no local arrays or inner
// loops with the lanes outermost, and no math function that sets errno (-fno-math-errno).
#pragma once

namespace plyimpact {

inline constexpr int kLanes = 8;

template <int N>
using LaneVec = double[N][kLanes];  // N components of kLanes elements
using LaneScalar = double[kLanes];

}  // namespace plyimpact

// On every lane kernel: a kernel called inside a lane loop, or one whose loops should fuse with the
// caller's, must be inlined for the loop to vectorise, and GCC's heuristics leave larger header
// functions out of line (a total-Lagrangian lane update called per lane ran scalar).
#define PLYIMPACT_LANE_KERNEL inline __attribute__((always_inline))

// `PLYIMPACT_LANES body` runs body for l = 0 .. kLanes-1 as one SIMD loop.
#define PLYIMPACT_LANES _Pragma("omp simd") for (int l = 0; l < ::plyimpact::kLanes; ++l)
