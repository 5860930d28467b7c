// Run-summary warning on negative contact energy (solver/contact_energy_watch). A penalty contact
// cannot give the bodies more energy than its springs took from them, so its energy below zero
// means the contact model created energy. The warning must name the contact, the time the energy
// first fell below -1 % of the reference energy and the lowest value. Reference answers here are
// the inputs themselves (the series are made up so the crossing time and minimum are known exactly).
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "run/contact_energy_watch.hpp"

namespace plyimpact {
namespace {

TEST(ContactEnergyWatch, WarnsWithNameFirstCrossingAndMinimum) {
  run::ContactEnergyWatch watch({"tup_plies", "self"});
  const double reference = 26.8;  // J; threshold -0.268 J
  // Contact 0: +0.01, -0.2 (above the threshold), -0.3 (crosses at t = 3e-6), -0.87 (minimum at
  // 4e-6), back to -0.1. Contact 1 stays at 0.
  const double e0[] = {0.01, -0.2, -0.3, -0.87, -0.1};
  for (int k = 0; k < 5; ++k) watch.observe({e0[k], 0.0}, 1e-6 * (k + 1), reference);
  const auto w = watch.warnings();
  ASSERT_EQ(w.size(), 1u);
  std::cout << w[0] << "\n";
  EXPECT_NE(w[0].find("'tup_plies'"), std::string::npos);
  EXPECT_NE(w[0].find("from t = 3e-06 s"), std::string::npos);
  EXPECT_NE(w[0].find("minimum -0.87 J at 4e-06 s"), std::string::npos);
  EXPECT_NE(w[0].find("-0.268 J"), std::string::npos);
}

TEST(ContactEnergyWatch, ExactlyAtTheThresholdOrWithoutReferenceDoesNotWarn) {
  run::ContactEnergyWatch watch({"c"});
  watch.observe({-0.01 * 10.0}, 1e-6, 10.0);  // equal to -1 %: not below
  watch.observe({-5.0}, 2e-6, 0.0);            // no reference energy: nothing to compare with
  EXPECT_TRUE(watch.warnings().empty());
  watch.observe({-0.1000001}, 3e-6, 10.0);
  EXPECT_EQ(watch.warnings().size(), 1u);
}

}  // namespace
}  // namespace plyimpact
