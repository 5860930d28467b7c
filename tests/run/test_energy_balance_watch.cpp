// The energy-balance check's rules (run/energy_balance_watch): the energy ratio stays within
// 1 +- 1 % at every sample, and no contributor energy (contact, interfaces) goes below -1e-6 of the
// reference energy. Reference answers are the inputs themselves: made-up balances whose extremes
// are known exactly.
//  - A run that stays inside passes with its extremes recorded and no warning.
//  - An excursion above and one below are both reported, each with its time, and the check fails.
//  - The start-up cycles (0-2) are not judged: their ratio is noise of the half step.
//  - A contact energy of -1e-9 of a 10 J run (round-off of a sum of non-negative increments) is not
//    negative; an interface energy of -2 mJ is, reported with its lowest value and time.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "run/energy_balance_watch.hpp"

namespace plyimpact {
namespace {

// A balance with the integrator's kinetic energy and two contributor terms (owners 0 and 1).
solver::Energies balance(double t, double contact, double interface) {
  solver::Energies e;
  e.time = t;
  e.terms[solver::Energies::kKinetic].value = 10.0;
  e.terms.push_back({"contact", "contact_energy", true, contact, 0});
  e.terms.push_back({"interface_elastic", "interface_elastic_energy", true, interface, 1});
  return e;
}

TEST(EnergyBalanceWatch, RunInsideTheBandPasses) {
  run::EnergyBalanceWatch w;
  w.observe(balance(1e-5, 0.0, 0.0), 1.0000, 10.0, 10);
  w.observe(balance(2e-5, 0.1, 0.0), 0.9950, 10.0, 20);
  w.observe(balance(3e-5, 0.2, 0.01), 1.0040, 10.0, 30);
  const run::EnergyBalanceVerdict v = w.verdict();
  EXPECT_TRUE(v.passed);
  EXPECT_DOUBLE_EQ(v.ratio_min, 0.995);
  EXPECT_DOUBLE_EQ(v.time_of_min, 2e-5);
  EXPECT_DOUBLE_EQ(v.ratio_max, 1.004);
  EXPECT_DOUBLE_EQ(v.time_of_max, 3e-5);
  EXPECT_DOUBLE_EQ(v.tolerance, 0.01);
  EXPECT_TRUE(v.negative.empty());
  EXPECT_TRUE(w.warnings().empty());
}

TEST(EnergyBalanceWatch, ExcursionsEitherWayFailWithTheirTimes) {
  run::EnergyBalanceWatch w;
  w.observe(balance(1e-5, 0.0, 0.0), 1.0000, 10.0, 10);
  w.observe(balance(2e-5, 0.0, 0.0), 1.0150, 10.0, 20);  // created 1.5 %
  w.observe(balance(3e-5, 0.0, 0.0), 0.9870, 10.0, 30);  // lost 1.3 %
  w.observe(balance(4e-5, 0.0, 0.0), 0.9990, 10.0, 40);
  const run::EnergyBalanceVerdict v = w.verdict();
  EXPECT_FALSE(v.passed);
  EXPECT_DOUBLE_EQ(v.ratio_max, 1.015);
  EXPECT_DOUBLE_EQ(v.time_of_max, 2e-5);
  EXPECT_DOUBLE_EQ(v.ratio_min, 0.987);
  EXPECT_DOUBLE_EQ(v.time_of_min, 3e-5);
  const std::vector<std::string> warnings = w.warnings();
  ASSERT_EQ(warnings.size(), 1u);
  std::cout << warnings[0] << "\n";
  EXPECT_NE(warnings[0].find("between 0.98700 (t = 3e-05 s) and 1.01500 (t = 2e-05 s)"), std::string::npos)
      << warnings[0];
}

TEST(EnergyBalanceWatch, StartUpCyclesAreNotJudged) {
  run::EnergyBalanceWatch w;
  w.observe(balance(1e-8, 0.0, -5.0), 2.0, 10.0, 1);  // cycle 1: the half step's noise
  w.observe(balance(1e-5, 0.0, 0.0), 1.0, 10.0, 3);
  const run::EnergyBalanceVerdict v = w.verdict();
  EXPECT_TRUE(v.passed);
  EXPECT_DOUBLE_EQ(v.ratio_max, 1.0);
}

TEST(EnergyBalanceWatch, NegativeContributorEnergyBeyondRoundOffFails) {
  run::EnergyBalanceWatch w;
  w.observe(balance(1e-5, -1e-8, 0.0), 1.0, 10.0, 10);    // -1e-9 of the run: round-off
  w.observe(balance(2e-5, 0.05, -0.002), 1.0, 10.0, 20);  // interface -2e-4 of the run
  w.observe(balance(3e-5, 0.06, -0.001), 1.0, 10.0, 30);
  const run::EnergyBalanceVerdict v = w.verdict();
  EXPECT_FALSE(v.passed);
  ASSERT_EQ(v.negative.size(), 1u);
  EXPECT_EQ(v.negative[0].key, "interface_elastic");
  EXPECT_DOUBLE_EQ(v.negative[0].value, -0.002);
  EXPECT_DOUBLE_EQ(v.negative[0].time, 2e-5);
  const std::vector<std::string> warnings = w.warnings();
  ASSERT_EQ(warnings.size(), 1u);
  std::cout << warnings[0] << "\n";
  EXPECT_NE(warnings[0].find("interface_elastic energy went negative: -0.002 J at t = 2e-05 s"), std::string::npos)
      << warnings[0];
}

}  // namespace
}  // namespace plyimpact
