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
// conserve energy to O(dt^2), so the same 0.2 ms runs at TSSFAC 0.9, 0.45 and 0.225 and the test
// asserts
//   - that elements did lose their matrix modulus in the hourglass modes (the path is exercised);
//   - second-order convergence at both halvings: error ratios > 3 (energy created or destroyed at
//     each failure would not shrink with the step: a ratio near 1);
//   - at the default TSSFAC 0.9 an error within the default scene's budget (energy ratio within
//     1 +- 0.01), and at 0.225 below a tenth of it.
// Measured: 6 of 12 elements degraded, errors 6.1e-3 / 1.18e-3 / 2.9e-4 (ratios 5.2 and 4.0). Why
// a quarter step for the tenth: the plies step at their thickness wave with the bulk viscosity
// damping that mode at Q2 (solver/element_step.hpp), so a compressing element's step is 0.94 L/c
// and TSSFAC 0.45 is already 0.42 L/c; the error there is the scheme's O(dt^2) at that step, as the
// clean 4.0 of the next halving shows. What it does not tell apart: booking the old half with the
// rescaled forces instead of the applied ones changes these errors by less than 10 % (the forces
// rescale when the matrix fails, at small hourglass forces along the matrix); the applied forces
// are kept because that booking is exact by construction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "ply_strip.hpp"
#include "hourglass/assumed_strain.hpp"

namespace plyimpact {
namespace {

constexpr double kDuration = 2e-4;  // s

struct BalanceRun {
  int degraded = 0;  // elements whose x' modulus fell to the lost-component floor
  test::StripBalance balance;
};

BalanceRun run_strip(double tssfac) {
  // 90-degree plies: fibre a along y, so the bending along x strains the matrix. DFAILT 0: nothing
  // erodes except on fibre-tension failure.
  const model::Model model = test::model_from_yaml(
      test::ply_strip_scene("A: [0, 1, 0], D: [-1, 0, 0], DFAILT: 0", "{ELFORM: 1, IHQ: 6, QM: 1}"), "strip.yaml");
  const std::vector<double> m0 = hourglass::assumed_strain_moduli(model, model.blocks[0]);
  BalanceRun r;
  r.balance = test::run_ply_strip(model, 20.0, tssfac, kDuration, [&](const solver::Solver& s) {
    const std::vector<double>& m = s.state().blocks[0].hourglass_moduli;
    for (std::size_t e = 0; e < model.blocks[0].size(); ++e)
      if (m[6 * e] < 1.01 * hourglass::kLostComponentResidual * m0[6 * e]) ++r.degraded;
    EXPECT_EQ(s.state().eroded_elements, 0);
  });
  return r;
}

TEST(FailedPlyHourglassEnergy, BalanceHoldsThroughEveryMatrixFailure) {
  const BalanceRun coarse = run_strip(0.9), fine = run_strip(0.45), finest = run_strip(0.225);
  std::cout << "failed-ply IHQ 6: " << coarse.degraded << " / " << fine.degraded << " / " << finest.degraded
            << " elements degraded by " << kDuration << " s at TSSFAC 0.9 / 0.45 / 0.225, largest balance error "
            << coarse.balance.worst << " / " << fine.balance.worst << " / " << finest.balance.worst
            << " of the initial energy (ratios " << coarse.balance.worst / fine.balance.worst << ", "
            << fine.balance.worst / finest.balance.worst << "), hourglass energy up to " << coarse.balance.hg_max
            << " of it\n";
  ASSERT_GT(fine.degraded, 0) << "the bottom ply's matrix should have failed";
  EXPECT_GT(coarse.balance.worst / fine.balance.worst, 3.0) << "the balance error should vanish as dt^2";
  EXPECT_LT(coarse.balance.worst, 1e-2) << "the default TSSFAC should keep the scene's energy budget";
  test::expect_second_order_balance(fine.balance, finest.balance);
}

}  // namespace
}  // namespace plyimpact
