// Energy balance when plies fail under the assumed-strain hourglass control (IHQ 6): a two-ply strip
// of *MAT_054 90-degree plies (fibre across the strip, so its bending strains the matrix), one
// element per 0.25 mm ply, 2.5 mm elements, simply supported at both ends, thrown into its first
// bending mode. The bottom ply's matrix fails in tension (YT) at mid-span while every element
// holds its own bending in the hourglass modes; DFAILT = 0, so nothing erodes. Each failing element
// switches to the degraded IHQ 6 moduli (E along the matrix -> 1e-3 of it) and rescales its stored
// forces (hourglass/assumed_strain.hpp, rescale_assumed_strain_forces); the work of the cycle's old
// forces is booked with the forces the nodes received.
// Reference: conservation of energy (the matrix's stress drop and the rescaled hourglass forces do
// no work; the stress and hourglass work are booked by the trapezoid rule). Central differences
// conserve energy to O(dt^2), so the same 0.2 ms runs at TSSFAC 0.9 and 0.45 and the test asserts
//   - that elements did lose their matrix modulus in the hourglass modes (the path is exercised);
//   - second-order convergence: error(0.9) / error(0.45) > 3 (energy created or destroyed at each
//     failure would not shrink with the step: a ratio near 1);
//   - at TSSFAC 0.45 an error below 1e-3 of the initial energy, a tenth of the default scene's
//     budget (energy ratio within 1 +- 0.01), and below that budget at 0.9.
// Measured: 6 of 12 elements degraded, errors 2.8e-3 / 7.1e-4 (ratio 3.9). What it does not tell
// apart: booking the old half with the rescaled forces instead of the applied ones changes these
// errors by less than 10 % (the forces rescale when the matrix fails, at small hourglass forces
// along the matrix); the applied forces are kept because that booking is exact by construction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "../core/support.hpp"
#include "hourglass/assumed_strain.hpp"

namespace plyimpact {
namespace {

constexpr double kLength = 0.015, kPly = 0.25e-3;
constexpr double kDuration = 2e-4;  // s

std::string strip_scene() {
  return "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
         "  m: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895, PRCB: 0.53,"
         " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [0, 1, 0], D: [-1, 0, 0], XT: 2.2e9, XC: 1.2e9, YT: 45e6,"
         " YC: 280e6, SC: 45e6, SOFT: 1, FBRT: 0, YCFAC: 2, CRIT: 54, BETA: 1, DFAILT: 0}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: 6, QM: 1}\n"
         "parts:\n  p: {material: m, section: s}\n"
         "mesh:\n  boxes:\n    - {part: p, size: [" + std::to_string(kLength) + ", 2.5e-3, " + std::to_string(2 * kPly) +
         "], elements: [6, 1, 2]}\n"
         "node_sets:\n  ends: {box: {min: [-1e-6, -1, -1], max: [1e-6, 1, 1]}}\n"
         "  ends2: {box: {min: [" + std::to_string(kLength - 1e-6) + ", -1, -1], max: [1, 1, 1]}}\n"
         "boundary_conditions:\n  - {node_set: ends, fix: [x, z]}\n  - {node_set: ends2, fix: [z]}\n";
}

struct BalanceRun {
  int degraded = 0;   // elements whose x' modulus fell to the lost-component floor
  double worst = 0;   // largest |balance error| / initial energy
  double hg_max = 0;  // largest hourglass energy / initial energy
};

BalanceRun run_strip(double tssfac) {
  model::Model model = test::model_from_yaml(strip_scene(), "strip.yaml");
  model.control.tssfac = tssfac;
  for (std::size_t n = 0; n < model.num_nodes(); ++n)
    model.v0[3 * n + 2] = -20.0 * std::sin(M_PI * model.X[3 * n] / kLength);  // m/s, first bending mode
  const std::vector<double> m0 = hourglass::assumed_strain_moduli(model, model.blocks[0]);
  solver::Solver s(model);
  const double e0 = s.state().initial_total_energy;
  BalanceRun r;
  while (s.state().time < kDuration) {
    s.step();
    const solver::Energies& e = s.balance();
    r.worst = std::max(r.worst, std::abs(e.total() - e0 - e.external_work()) / e0);
    r.hg_max = std::max(r.hg_max, e.hourglass() / e0);
  }
  const std::vector<double>& m = s.state().blocks[0].hourglass_moduli;
  for (std::size_t e = 0; e < model.blocks[0].size(); ++e)
    if (m[6 * e] < 1.01 * hourglass::kLostComponentResidual * m0[6 * e]) ++r.degraded;
  EXPECT_EQ(s.state().eroded_elements, 0);
  return r;
}

TEST(FailedPlyHourglassEnergy, BalanceHoldsThroughEveryMatrixFailure) {
  const BalanceRun coarse = run_strip(0.9), fine = run_strip(0.45);
  std::cout << "failed-ply IHQ 6: " << coarse.degraded << " / " << fine.degraded
            << " elements degraded by " << kDuration << " s at TSSFAC 0.9 / 0.45, largest balance error "
            << coarse.worst << " / " << fine.worst << " of the initial energy (ratio " << coarse.worst / fine.worst
            << "), hourglass energy up to " << coarse.hg_max << " of it\n";
  ASSERT_GT(fine.degraded, 0) << "the bottom ply's matrix should have failed";
  EXPECT_GT(coarse.hg_max, 1e-3) << "the hourglass modes should hold a share of the energy";
  EXPECT_GT(coarse.worst / fine.worst, 3.0) << "the balance error should vanish as dt^2";
  EXPECT_LT(fine.worst, 1e-3);
  EXPECT_LT(coarse.worst, 1e-2);
}

}  // namespace
}  // namespace plyimpact
