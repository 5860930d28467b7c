// Where a run's wall time went (run/run_timing.hpp): summary.json's `timing` and the table printed
// at the end of `plyimpact run`. Checked on the eroding impact scene (restart_scenes.hpp: a rigid
// sphere through an eroding contact into a *MAT_054 plate, ~200 cycles):
//  - every part that ran has its row: set-up, the solver's phases (node update, element pass,
//    element checks, the contact and the rigid body by name), the solver outside the phases, frames,
//    interface frames, history, progress line, the run checks and the restart dump at the stop;
//  - the solver's rows add up to the solver time behind ns_per_element_cycle (a separate sum over
//    the cycles in the run loop): equal to 1e-9 relative, the round-off of adding ~10 rows;
//  - the rows account for the span they claim (set-up to the stop) to within 10 %: what they leave
//    out is the loop's own few statements per cycle between the timed calls, microseconds in a span
//    of tens of milliseconds; no row is negative and together they never exceed the span.
// And RunTiming itself: rows of one name merge, the table lists them largest first.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "output/json_reader.hpp"
#include "restart_scenes.hpp"
#include "run/run_timing.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

TEST(RunTiming, RowsOfOneNameMergeAndTheTableListsThemLargestFirst) {
  run::RunTiming t;
  t.add("contact", 1.0);
  t.add("element pass", 3.0);
  t.add("contact", 0.5);
  t.span = 5.0;
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[0].name, "contact");
  EXPECT_DOUBLE_EQ(t.rows()[0].seconds, 1.5);
  EXPECT_DOUBLE_EQ(t.accounted(), 4.5);
  const std::string table = run::timing_table(t);
  EXPECT_LT(table.find("element pass"), table.find("contact"));
  EXPECT_NE(table.find("60.0 %"), std::string::npos) << table;
}

TEST(RunTiming, SummaryAccountsForTheRunByPart) {
  const test::TestDir tmp;
  const fs::path scene = test::write_file(tmp / "impact.yaml", test::kImpactScene);
  const auto r = test::plyimpact({"run", scene.string(), "-o", (tmp / "out").string(), "--threads", "1"});
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("where the wall time went"), std::string::npos) << r.out;

  const output::Json summary = output::parse_json(test::read_file(tmp / "out" / "summary.json"), "summary.json");
  const output::Json& timing = *summary.find("timing");
  std::map<std::string, double> rows;
  double sum = 0;
  for (const output::Json& row : timing.find("rows")->as_array()) {
    const double s = row.find("seconds")->as_number();
    EXPECT_GE(s, 0.0) << row.find("name")->as_string();
    rows[row.find("name")->as_string()] = s;
    sum += s;
  }
  const std::set<std::string> outside_solver = {"set-up (solver, first output)", "frames (VTU)",
                                                 "interface frames (VTU)", "history (CSV)", "run checks",
                                                 "progress line", "restart dumps"};
  const std::set<std::string> solver_rows = {"node update", "element pass", "element checks",
                                             "solver, outside the phases", "contact", "rigid_bodies"};
  for (const auto& names : {outside_solver, solver_rows})
    for (const std::string& name : names) EXPECT_EQ(rows.count(name), 1u) << "no row " << name;
  EXPECT_EQ(rows.size(), outside_solver.size() + solver_rows.size());

  const double span = timing.find("span")->as_number();
  EXPECT_NEAR(timing.find("accounted")->as_number(), sum, 1e-12 * span);
  EXPECT_LE(sum, span * (1 + 1e-9));
  EXPECT_GE(sum, 0.9 * span);

  double solver = 0;
  for (const std::string& name : solver_rows) solver += rows[name];
  const double element_cycles = summary.find("elements")->as_number() * summary.find("cycles")->as_number();
  const double solver_seconds = 1e-9 * summary.find("ns_per_element_cycle")->as_number() * element_cycles;
  EXPECT_NEAR(solver, solver_seconds, 1e-9 * solver_seconds);
}

}  // namespace
}  // namespace plyimpact
