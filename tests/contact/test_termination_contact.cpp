// control.termination_contact (*TERMINATION_CONTACT) on the Hertz impact of hertz_scene.hpp (a/h = 3):
// the cap strikes the block and rebounds, and nothing acts on it once it has left. The reference is
// the same model stepped cycle by cycle with the rule's test done by hand on the contact's resultant:
// from ACTIM (half the Hertz contact time, mid-impact) the first cycle at or below THRES starts the
// force-free stretch, and the run must end at the first cycle DUR after it. run_loop with the rule
// must end there exactly (same model, same cycles: the cycle count and the time are equal, not
// close), as completed, long before the scene's termination_time of 1 s; in the reference the cap
// moves away from the block by then. THRES 0 (the resultant is exactly zero once no spring acts) and a
// threshold of 10 % of the Hertz peak, which the rebound's tail crosses earlier.
#include <gtest/gtest.h>

#include <string>

#include "hertz_scene.hpp"
#include "run/contact_termination.hpp"
#include "run/run.hpp"

namespace plyimpact {
namespace {

using namespace test::hertz;

struct Expected {
  long cycles = 0;
  double time = 0, velocity = 0;
};

Expected by_hand(const model::Model& model, const config::TerminationContactSpec& rule) {
  solver::Solver solver(model);
  double quiet_since = -1;
  while (true) {
    solver.step();
    const double t = solver.state().time;
    if (t < rule.ACTIM) continue;
    const Vec3& r = solver.contacts()[0].forces().resultant;
    const double f = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (f > rule.THRES) {
      quiet_since = -1;
      continue;
    }
    if (quiet_since < 0) quiet_since = t;
    if (t - quiet_since >= rule.DUR * (1 - 1e-12)) return {solver.state().cycle, t, solver.rigid_bodies()[0].v[2]};
  }
}

TEST(TerminationContact, EndsTheRunWhereTheContactHasBeenFreeForDur) {
  const Hertz hz;
  for (double thres : {0.0, 0.1 * hz.f_max / 4}) {  // the quarter model carries a quarter of the force
    model::Model model = build(3);
    config::TerminationContactSpec rule;
    rule.contact = "hertz";
    rule.ACTIM = 0.5 * hz.t_c;
    rule.THRES = thres;
    rule.DUR = 2e-6;
    model.control.termination_contact = rule;
    const Expected want = by_hand(model, rule);
    EXPECT_GT(want.time, hz.t_c) << "the rule meets after the impact";
    EXPECT_LT(want.time, 2 * hz.t_c);
    EXPECT_GT(want.velocity, 0) << "the cap has rebounded";

    run::ContactTermination termination(rule);
    const run::RunReport report = run::run_loop(model, {&termination});
    EXPECT_TRUE(report.completed);
    EXPECT_FALSE(report.failed);
    EXPECT_EQ(report.cycles, want.cycles) << "THRES " << thres;
    EXPECT_EQ(report.end_time, want.time);
    EXPECT_LT(report.end_time, model.control.termination_time);
    EXPECT_NE(report.termination.find("contact 'hertz'"), std::string::npos) << report.termination;
  }
}

TEST(TerminationContact, AContactTheModelLacksIsARunError) {
  model::Model model = build(3);
  config::TerminationContactSpec rule;
  rule.contact = "nothing";
  run::ContactTermination termination(rule);
  const run::RunReport report = run::run_loop(model, {&termination});
  EXPECT_TRUE(report.failed);
  EXPECT_NE(report.stop_reason.find("contact 'nothing'"), std::string::npos) << report.stop_reason;
}

}  // namespace
}  // namespace plyimpact
