// Ballistic limit by bracketing against an analytic residual-velocity law injected as the case
// function: the Lambert-Jonas curve v_r = a (v^p - v_bl^p)^(1/p) with a = 0.8, p = 2 and a known
// v_bl = 312.3 m/s, a 10 % rebound below it. The search must end with a bracket no wider than the
// tolerance that contains v_bl (so the mid-point is within tolerance / 2 of it: the stated answer
// is exact, no other tolerance applies), after exactly the number of rounds the bracket's width
// needs (bisection: ceil(log2(W / tol)); two cases a round: ceil(log3(W / tol))), i.e. it stops at
// the tolerance and not later. A bracket whose low end perforates, or whose high end does not, is
// refused naming the study line; an undecided run stops the search and asks for a longer run.
// The perforation criterion is checked on synthetic histories of a deformable impactor.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "study/ballistic_limit.hpp"

namespace plyimpact::study {
namespace {

constexpr double kLimit = 312.3;

struct Law {
  int calls = 0;
  std::vector<Shot> operator()(const std::vector<double>& v) {
    std::vector<Shot> out;
    for (double x : v) {
      ++calls;
      const bool through = x > kLimit;
      out.push_back({x, through ? 0.8 * std::sqrt(x * x - kLimit * kLimit) : -0.1 * x,
                     through ? Perforation::perforated : Perforation::stopped, ""});
    }
    return out;
  }
};

BracketSearch bracket(double lo, double hi, double tol, int points) {
  return {lo, hi, tol, points, "study.yaml:9:18: ballistic_limit"};
}

TEST(BallisticLimit, BisectionConvergesToTheKnownLimitAndStopsAtTheTolerance) {
  Law law;
  const auto b = search_ballistic_limit(bracket(100, 700, 2, 1), std::ref(law));
  EXPECT_LE(b.hi - b.lo, 2.0);
  EXPECT_LT(b.lo, kLimit);
  EXPECT_GT(b.hi, kLimit);
  EXPECT_NEAR(b.limit, kLimit, 1.0);
  EXPECT_EQ(b.rounds, 9) << "600 / 2^9 = 1.17 <= 2 < 600 / 2^8";
  EXPECT_EQ(law.calls, 2 + 9);
  ASSERT_EQ(b.shots.size(), 11u);
  EXPECT_EQ(b.shots[0].velocity, 100);
  EXPECT_EQ(b.shots[1].velocity, 700);
  EXPECT_EQ(b.shots[2].velocity, 400) << "the first bisection is the mid-point";
}

TEST(BallisticLimit, TwoCasesARoundCutTheBracketInThree) {
  Law law;
  const auto b = search_ballistic_limit(bracket(100, 700, 2, 2), std::ref(law));
  EXPECT_LE(b.hi - b.lo, 2.0);
  EXPECT_LT(b.lo, kLimit);
  EXPECT_GT(b.hi, kLimit);
  EXPECT_EQ(b.rounds, 6) << "600 / 3^6 = 0.82 <= 2 < 600 / 3^5";
  EXPECT_EQ(law.calls, 2 + 2 * 6);
}

TEST(BallisticLimit, KnownSweepCasesNarrowTheBracket) {
  Law law;
  const std::vector<Shot> sweep = law({200, 300, 350, 500});
  law.calls = 0;
  const auto b = search_ballistic_limit(bracket(100, 700, 2, 1), std::ref(law), sweep);
  EXPECT_EQ(b.rounds, 5) << "from [300, 350]: 50 / 2^5 = 1.6 <= 2 < 50 / 2^4";
  EXPECT_EQ(law.calls, 2 + 5);
  EXPECT_LT(b.lo, kLimit);
  EXPECT_GT(b.hi, kLimit);
}

TEST(BallisticLimit, RefusesABracketThatDoesNotBracket) {
  for (const auto& [lo, hi] : {std::pair{400.0, 700.0}, std::pair{100.0, 300.0}}) {
    Law law;
    try {
      search_ballistic_limit(bracket(lo, hi, 2, 1), std::ref(law));
      FAIL() << "[" << lo << ", " << hi << "] does not contain " << kLimit;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("study.yaml:9:18: ballistic_limit"), std::string::npos) << m;
      EXPECT_NE(m.find("does not bracket"), std::string::npos) << m;
    }
    EXPECT_EQ(law.calls, 2) << "only the two ends run";
  }
  Law law;
  EXPECT_THROW(search_ballistic_limit(bracket(300, 200, 2, 1), std::ref(law)), InputError);
  EXPECT_EQ(law.calls, 0);
}

TEST(BallisticLimit, AnUndecidedRunEndsTheSearchAskingForALongerRun) {
  auto shoot = [](const std::vector<double>& v) {
    std::vector<Shot> out;
    for (double x : v)
      out.push_back({x, 5, x >= 600 ? Perforation::perforated : x <= 100 ? Perforation::stopped : Perforation::undecided,
                     "case_x"});
    return out;
  };
  try {
    search_ballistic_limit(bracket(100, 700, 2, 1), shoot);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("control.termination_time"), std::string::npos) << e.what();
  }
}

// A deformable impactor moving along -z from z = 10 mm at 100 m/s; after the impact it moves at
// `v_end` along z from t = 0.5 on (free flight) or with a changing velocity (still in contact).
RunRecord flight(double v_end, double travel, bool free) {
  RunRecord r;
  r.history = output::HistoryTable(
      {"time", "impactor_x", "impactor_y", "impactor_z", "impactor_vx", "impactor_vy", "impactor_vz"});
  const double rows[][2] = {{0, -100}, {0.5, v_end}, {0.92, free ? v_end : v_end * 1.5}, {0.96, v_end}, {1.0, v_end}};
  for (const auto& [t, vz] : rows)
    r.history.add_row(std::vector<double>{t, 0, 0, t == 0 ? 0.01 : 0.01 - travel * t, 0, 0, vz});
  return r;
}

TEST(BallisticLimit, PerforationCriterion) {
  const double pass = 2.1e-3;  // gap 0.1 mm + 2 mm plate
  EXPECT_EQ(classify(flight(-40, 0.01, true), pass), Perforation::perforated);
  EXPECT_EQ(classify(flight(+5, 0.001, true), pass), Perforation::stopped) << "rebound";
  EXPECT_EQ(classify(flight(0, 0.001, true), pass), Perforation::stopped) << "arrested";
  RunRecord carried = flight(-3, 0.001, false);  // still pushing into the plate at the end
  EXPECT_EQ(classify(carried, pass), Perforation::undecided) << "never at rest: the run is too short";
  carried.history.add_row(std::vector<double>{1.01, 0, 0, 0.0099, 0, 0, 0.5});  // rebounds, then the plate
  carried.history.add_row(std::vector<double>{1.02, 0, 0, 0.0099, 0, 0, -3});
  EXPECT_EQ(classify(carried, pass), Perforation::stopped) << "once at rest, arrested whatever follows";
  EXPECT_EQ(classify(flight(-40, 0.01, false), pass), Perforation::undecided) << "still decelerating in the last tenth";
  EXPECT_EQ(classify(flight(-40, 0.001, true), pass), Perforation::undecided) << "nose not yet past the rear face";
  EXPECT_THROW(classify(flight(-40, 0.01, true), std::nan("")), NotAvailable);
}

}  // namespace
}  // namespace plyimpact::study
