// The hourglass warning's rule (run/hourglass_watch): hourglass energy over max(peak internal
// energy, 1 % of the reference energy). Reference answers are the inputs themselves: made-up
// series whose ratios are known exactly.
//  - The false alarm: at first contact the internal energy is round-off (1e-37 J) and the
//    hourglass energy 1e-33 J; a plain ratio to the peak internal energy read 1e6 %. Against the
//    floor (1 % of a 10 J run: 0.1 J) it is 1e-32: no warning.
//  - A true warning: later the internal energy is 2 J and the hourglass energy 0.5 J, 25 % of the
//    peak internal energy (above a 10 % limit): warned, with 25.0 %, the time and the rule.
//  - Hourglass energy in a run whose internal energy stays tiny is judged against the floor:
//    0.02 J over 0.1 J = 20 %, warned, saying the floor governed.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "run/hourglass_watch.hpp"

namespace plyimpact {
namespace {

TEST(HourglassWatch, RoundOffInternalEnergyRaisesNoFalseAlarm) {
  run::HourglassWatch w(0.1);
  w.observe(1e-6, 1e-33, 1e-37, 10.0);
  EXPECT_FALSE(w.exceeded());
  EXPECT_NEAR(w.max_ratio(), 1e-32, 1e-46);
  EXPECT_TRUE(w.warning().empty());
}

TEST(HourglassWatch, ShareOfThePeakInternalEnergyWarnsWithTimeAndRule) {
  run::HourglassWatch w(0.1);
  w.observe(1e-6, 1e-33, 1e-37, 10.0);
  w.observe(2e-5, 0.2, 4.0, 10.0);  // 5 %
  w.observe(3e-5, 0.5, 2.0, 10.0);  // 0.5 / peak 4 = 12.5 %
  w.observe(4e-5, 1.0, 1.0, 10.0);  // 1 / 4 = 25 %
  ASSERT_TRUE(w.exceeded());
  EXPECT_DOUBLE_EQ(w.max_ratio(), 0.25);
  const std::string s = w.warning();
  std::cout << s << "\n";
  EXPECT_NE(s.find("25.0% of the peak internal energy"), std::string::npos) << s;
  EXPECT_NE(s.find("t = 4e-05 s"), std::string::npos) << s;
  EXPECT_NE(s.find("rule: hourglass energy / max(peak internal energy, 1% of the initial energy + external work)"),
            std::string::npos) << s;
}

TEST(HourglassWatch, TinyInternalEnergyIsJudgedAgainstTheFloor) {
  run::HourglassWatch w(0.1);
  w.observe(1e-5, 0.02, 0.001, 10.0);
  ASSERT_TRUE(w.exceeded());
  EXPECT_DOUBLE_EQ(w.max_ratio(), 0.2);
  EXPECT_NE(w.warning().find("floor of 1% of the run's energy"), std::string::npos) << w.warning();
}

}  // namespace
}  // namespace plyimpact
