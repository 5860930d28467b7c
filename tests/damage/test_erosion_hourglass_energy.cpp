// Energy balance when elements erode next to neighbours whose hourglass modes hold energy: a
// two-ply strip of *MAT_054 0-degree plies, one element per 0.25 mm ply (the default scene's
// discretisation), 2.5 mm elements, simply supported at both ends, thrown into its first bending
// mode. One-point plies carry their own bending in the hourglass modes, so every element holds
// hourglass energy (elastic for IHQ 5 and 6, dissipated for IHQ 2); the bottom ply's fibre strain
// reaches DFAILT at mid-span and elements erode there while their neighbours keep bending.
// Reference: conservation of energy. The balance (kinetic + internal + hourglass + bulk viscous,
// eroded elements' energy kept in their terms) must stay at its initial value through every
// erosion. Tolerance 1e-3 of the initial energy, a tenth of the default scene's budget (energy
// ratio within 1 +- 0.01): a form that created energy where elements erode beside hourglass-loaded
// neighbours (as IHQ 6 was suspected to in the default scene, before that gain was traced to the
// contact, docs/theory.md section 10) would show it here, where nothing else can. Measured: the
// largest error 1.4e-4 (IHQ 2), 7.5e-4 (IHQ 5), 2.7e-4 (IHQ 6), reached by drift over the violent
// motion after the strip breaks (strain rates of 1e3/s, large rotations), not in steps at the
// erosions (the printed balance at each erosion).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "../core/support.hpp"

namespace plyimpact {
namespace {

constexpr double kLength = 0.015, kPly = 0.25e-3;

std::string strip_scene(int ihq, double qm) {
  return "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
         "  m: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895, PRCB: 0.53,"
         " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], XT: 2.2e9, XC: 1.2e9, YT: 45e6,"
         " YC: 280e6, SC: 45e6, SOFT: 1, FBRT: 0, YCFAC: 2, CRIT: 54, BETA: 1, DFAILT: 0.0015, DFAILC: -0.0105,"
         " DFAILM: 0.0105, DFAILS: 0}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: " + std::to_string(ihq) + ", QM: " + std::to_string(qm) + "}\n"
         "parts:\n  p: {material: m, section: s}\n"
         "mesh:\n  boxes:\n    - {part: p, size: [" + std::to_string(kLength) + ", 2.5e-3, " + std::to_string(2 * kPly) +
         "], elements: [6, 1, 2]}\n"
         "node_sets:\n  ends: {box: {min: [-1e-6, -1, -1], max: [1e-6, 1, 1]}}\n"
         "  ends2: {box: {min: [" + std::to_string(kLength - 1e-6) + ", -1, -1], max: [1, 1, 1]}}\n"
         "boundary_conditions:\n  - {node_set: ends, fix: [x, z]}\n  - {node_set: ends2, fix: [z]}\n";
}

class ErosionHourglassEnergy : public ::testing::TestWithParam<std::pair<int, double>> {};

TEST_P(ErosionHourglassEnergy, BalanceHoldsThroughEveryErosion) {
  const auto [ihq, qm] = GetParam();
  model::Model model = test::model_from_yaml(strip_scene(ihq, qm), "strip.yaml");
  for (std::size_t n = 0; n < model.num_nodes(); ++n)
    model.v0[3 * n + 2] = -30.0 * std::sin(M_PI * model.X[3 * n] / kLength);  // m/s, first bending mode
  solver::Solver s(model);
  const double e0 = s.state().initial_total_energy;
  double worst = 0, hg_max = 0;
  long eroded = 0;
  for (int i = 0; i < 40000 && s.state().eroded_elements < 6; ++i) {
    s.step();
    const solver::Energies& e = s.balance();
    worst = std::max(worst, std::abs(e.total() - e0 - e.external_work()) / e0);
    hg_max = std::max(hg_max, e.hourglass());
    if (s.state().eroded_elements != eroded)
      std::cout << "  t " << s.state().time << " s: " << s.state().eroded_elements << " eroded, balance "
                << (e.total() - e0 - e.external_work()) / e0 << ", hourglass " << e.hourglass() / e0 << "\n";
    eroded = s.state().eroded_elements;
  }
  std::cout << "IHQ " << ihq << " QM " << qm << ": " << eroded << " elements eroded by t = " << s.state().time
            << " s, largest balance error " << worst << " of the initial energy, hourglass energy up to "
            << hg_max / e0 << " of it\n";
  ASSERT_GT(eroded, 0) << "the strip should have failed in fibre tension";
  EXPECT_GT(hg_max, 1e-3 * e0) << "the hourglass modes should hold a share of the energy";
  EXPECT_LT(worst, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(IHQ, ErosionHourglassEnergy,
                         ::testing::Values(std::pair{2, 0.1}, std::pair{5, 0.1}, std::pair{6, 1.0}),
                         [](const auto& info) { return "IHQ" + std::to_string(info.param.first); });

}  // namespace
}  // namespace plyimpact
