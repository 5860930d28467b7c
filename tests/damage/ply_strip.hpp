// The strip of the energy tests through ply failure and erosion: two *MAT_054 T800S/M21 plies of
// 0.25 mm, one element per ply, 6 elements of 2.5 mm along its 15 mm, simply supported at both ends
// (x and z fixed at x = 0, z at x = L), thrown into its first bending mode. The tests choose the
// ply axes and strains to failure (`axes_and_failure`, the card's AOPT 2 vectors and DFAIL* fields)
// and the section.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../core/support.hpp"

namespace plyimpact::test {

inline constexpr double kStripLength = 0.015, kStripPly = 0.25e-3;

inline std::string ply_strip_scene(const std::string& axes_and_failure, const std::string& section) {
  return "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
         "  m: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895, PRCB: 0.53,"
         " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, XT: 2.2e9, XC: 1.2e9, YT: 45e6, YC: 280e6, SC: 45e6, SOFT: 1, FBRT: 0,"
         " YCFAC: 2, CRIT: 54, BETA: 1, AOPT: 2, " + axes_and_failure + "}\n"
         "sections:\n  s: " + section + "\n"
         "parts:\n  p: {material: m, section: s}\n"
         "mesh:\n  boxes:\n    - {part: p, size: [" + std::to_string(kStripLength) + ", 2.5e-3, " +
         std::to_string(2 * kStripPly) + "], elements: [6, 1, 2]}\n"
         "node_sets:\n  ends: {box: {min: [-1e-6, -1, -1], max: [1e-6, 1, 1]}}\n"
         "  ends2: {box: {min: [" + std::to_string(kStripLength - 1e-6) + ", -1, -1], max: [1, 1, 1]}}\n"
         "boundary_conditions:\n  - {node_set: ends, fix: [x, z]}\n  - {node_set: ends2, fix: [z]}\n";
}

// Largest |balance error| and hourglass energy over a run, both relative to the initial energy.
struct StripBalance {
  double worst = 0;
  double hg_max = 0;
};

// Runs the strip's model from its first bending mode (mid-span velocity v_mid, m/s, downwards) for
// `duration` seconds at `tssfac`; `finish(solver)` is called at the end.
template <class Finish>
StripBalance run_ply_strip(model::Model model, double v_mid, double tssfac, double duration, Finish&& finish) {
  model.control.tssfac = tssfac;
  for (std::size_t n = 0; n < model.num_nodes(); ++n)
    model.v0[3 * n + 2] = -v_mid * std::sin(M_PI * model.X[3 * n] / kStripLength);
  solver::Solver s(model);
  const double e0 = s.state().initial_total_energy;
  StripBalance r;
  while (s.state().time < duration) {
    s.step();
    const solver::Energies& e = s.balance();
    r.worst = std::max(r.worst, std::abs(e.total() - e0 - e.external_work()) / e0);
    r.hg_max = std::max(r.hg_max, e.hourglass() / e0);
  }
  finish(s);
  return r;
}

// What both strip tests assert of the same run at two steps, the fine one half the coarse (TSSFAC
// 0.9 and 0.45, or 0.45 and 0.225): the hourglass modes hold a share of the energy; the balance
// error vanishes as dt^2 (a ratio above 3, where 4 is dt^2 and energy created or destroyed at a
// failure would give about 1); it stays below 1e-3 of the initial energy at the fine step, a tenth
// of the default scene's budget, and below that budget at the coarse one.
inline void expect_second_order_balance(const StripBalance& coarse, const StripBalance& fine) {
  EXPECT_GT(coarse.hg_max, 1e-3) << "the hourglass modes should hold a share of the energy";
  EXPECT_GT(coarse.worst / fine.worst, 3.0) << "the balance error should vanish as dt^2";
  EXPECT_LT(fine.worst, 1e-3);
  EXPECT_LT(coarse.worst, 1e-2);
}

}  // namespace plyimpact::test
