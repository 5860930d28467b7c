// Where a run's wall time went, by part of the cycle and of the output (LS-DYNA prints the like as
// its timing summary at the end of a run): the solver's phases (Solver::phase_times: node update,
// element pass, element checks, each force contributor), the solver's own bookkeeping outside them,
// every observer (frames, history, checks, ...), restart dumps and the set-up before the first
// cycle. In summary.json (`timing`) and printed at the end of `plyimpact run`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace plyimpact::run {

struct TimingRow {
  std::string name;
  double seconds = 0;  // wall
};

class RunTiming {
 public:
  // Adds to the row of that name (rows keep the order in which their names first came).
  void add(std::string_view name, double seconds);
  const std::vector<TimingRow>& rows() const { return rows_; }
  double accounted() const;  // s, sum of the rows
  // Wall seconds of the span the rows account for (set-up to the stop, without the stop's writes).
  double span = 0;

 private:
  std::vector<TimingRow> rows_;
};

// The rows as a text table, largest first: name, seconds, share of the span.
std::string timing_table(const RunTiming& timing);

}  // namespace plyimpact::run
