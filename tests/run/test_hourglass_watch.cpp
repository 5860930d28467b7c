// The hourglass check's rule (run/hourglass_watch): hourglass energy over max(internal energy at the
// same time, 1 % of the reference energy), its maximum over the run and pass/fail against the
// limit. Reference answers are the inputs themselves: made-up series whose ratios are known exactly.
//  - At first contact the internal energy is round-off (1e-37 J) and the hourglass energy 1e-33 J;
//    a plain ratio reads 1e6 %. Against the floor (1 % of a 10 J run: 0.1 J) it is 1e-32: passed.
//  - The maximum over time, with the internal energy of the same time: the internal energy peaks
//    at 4 J and falls to 1 J (the plate springs back) while 0.5 J stays in hourglass modes: 50 %
//    at the last sample, although only 12.5 % of the peak internal energy. Failed, with the time.
//  - Hourglass energy in a run whose internal energy stays tiny is judged against the floor:
//    0.02 J over 0.1 J = 20 %, failed, saying the floor governed.
//  - A run that stays below the limit passes and leaves no warning.
//  - The per-part energies recorded at the maximum stay with it, and the warning names the largest.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "run/hourglass_watch.hpp"

namespace plyimpact {
namespace {

TEST(HourglassWatch, RoundOffInternalEnergyRaisesNoFalseAlarm) {
  run::HourglassWatch w(0.1);
  w.observe(1e-6, 1e-33, 1e-37, 10.0);
  EXPECT_FALSE(w.exceeded());
  EXPECT_NEAR(w.max_ratio(), 1e-32, 1e-46);
  EXPECT_TRUE(w.warning().empty());
  EXPECT_TRUE(w.verdict().passed);
}

TEST(HourglassWatch, MaximumOverTimeUsesTheInternalEnergyOfTheSameTime) {
  run::HourglassWatch w(0.1);
  w.observe(1e-6, 1e-33, 1e-37, 10.0);
  w.observe(2e-5, 0.2, 4.0, 10.0);  // 5 %
  w.observe(3e-5, 0.5, 2.0, 10.0);  // 25 %
  w.observe(4e-5, 0.5, 1.0, 10.0);  // 50 %
  w.observe(5e-5, 0.5, 2.5, 10.0);  // 20 %: the maximum stays
  ASSERT_TRUE(w.exceeded());
  EXPECT_DOUBLE_EQ(w.max_ratio(), 0.5);
  const run::HourglassVerdict v = w.verdict();
  EXPECT_FALSE(v.passed);
  EXPECT_DOUBLE_EQ(v.time, 4e-5);
  EXPECT_DOUBLE_EQ(v.hourglass, 0.5);
  EXPECT_DOUBLE_EQ(v.denominator, 1.0);
  EXPECT_DOUBLE_EQ(v.limit, 0.1);
  EXPECT_FALSE(v.floor_governs);
  const std::string s = w.warning();
  std::cout << s << "\n";
  EXPECT_NE(s.find("50.0% of the internal energy"), std::string::npos) << s;
  EXPECT_NE(s.find("t = 4e-05 s"), std::string::npos) << s;
  EXPECT_NE(s.find("rule: hourglass energy / max(internal energy, 1% of the initial energy + external work)"),
            std::string::npos) << s;
}

TEST(HourglassWatch, TinyInternalEnergyIsJudgedAgainstTheFloor) {
  run::HourglassWatch w(0.1);
  w.observe(1e-5, 0.02, 0.001, 10.0);
  ASSERT_TRUE(w.exceeded());
  EXPECT_DOUBLE_EQ(w.max_ratio(), 0.2);
  EXPECT_TRUE(w.verdict().floor_governs);
  EXPECT_NE(w.warning().find("floor of 1% of the run's energy"), std::string::npos) << w.warning();
}

// What eroded elements held is reported with the maximum, and the advice follows where it is.
TEST(HourglassWatch, ErodedShareIsReportedWithTheMaximum) {
  run::HourglassWatch w(0.1);
  w.observe(1e-5, 0.05, 1.0, 10.0, 0.0);
  w.observe(2e-5, 0.4, 1.0, 10.0, 0.3);
  w.observe(3e-5, 0.3, 1.0, 10.0, 0.3);  // smaller share: not the maximum
  EXPECT_DOUBLE_EQ(w.verdict().eroded_hourglass, 0.3);
  const std::string s = w.warning();
  EXPECT_NE(s.find("0.3 J of it held by eroded elements"), std::string::npos) << s;
  EXPECT_NE(s.find("before they eroded"), std::string::npos) << s;

  run::HourglassWatch live(0.1);
  live.observe(1e-5, 0.4, 1.0, 10.0, 0.1);
  EXPECT_NE(live.warning().find("use IHQ 6"), std::string::npos) << live.warning();
}

// Where it is: the per-part energies recorded at a new maximum are kept with it (a later, smaller
// share does not replace them), and the warning names the part holding the most.
TEST(HourglassWatch, PartsAtTheMaximumAreKeptAndTheLargestNamed) {
  run::HourglassWatch w(0.1);
  w.name_parts({"ply_1_0", "ply_1_0_zone", "impactor"});
  EXPECT_TRUE(w.observe(1e-5, 0.2, 1.0, 10.0));
  w.record_by_part({0.05, 0.0, 0.15});
  EXPECT_TRUE(w.observe(2e-5, 0.4, 1.0, 10.0));  // a new maximum: its own parts
  w.record_by_part({0.3, 0.0, 0.1});
  EXPECT_FALSE(w.observe(3e-5, 0.3, 1.0, 10.0));  // smaller share: nothing to record
  const run::HourglassVerdict v = w.verdict();
  EXPECT_EQ(v.by_part, (std::vector<double>{0.3, 0.0, 0.1}));
  const std::string s = w.warning();
  EXPECT_NE(s.find("the most in part ply_1_0 (0.3 J"), std::string::npos) << s;
  EXPECT_TRUE(w.observe(4e-5, 0.6, 1.0, 10.0));  // a new maximum not yet recorded: no stale parts
  EXPECT_TRUE(w.verdict().by_part.empty());
  EXPECT_EQ(w.warning().find("the most in part"), std::string::npos) << w.warning();
}

TEST(HourglassWatch, RunBelowTheLimitPasses) {
  run::HourglassWatch w(0.1);
  w.observe(1e-5, 0.05, 1.0, 10.0);  // 5 %
  w.observe(2e-5, 0.18, 2.0, 10.0);  // 9 %
  EXPECT_FALSE(w.exceeded());
  EXPECT_DOUBLE_EQ(w.max_ratio(), 0.09);
  EXPECT_TRUE(w.verdict().passed);
  EXPECT_TRUE(w.warning().empty());
}

}  // namespace
}  // namespace plyimpact
