// history.csv: one row per history interval (energies, step, reactions, contact, wall and rigid-body
// columns, erosion). The file is written atomically at the start (header and the row at t = 0),
// then grows by whole rows appended at most a second of wall time after they were computed (one
// write() each, cut back if it fails, so the file is a valid CSV of the rows so far at any moment),
// and is rewritten atomically at the end, so the final file is exactly the table whatever happened
// in between. A run continued from a dump rewrites it from the dump's rows and goes on appending.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "output/atomic_file.hpp"
#include "output/history_table.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

// Columns of a run observer that measures something of its own (the coupon probe), appended
// after the solver's columns.
class HistoryColumns {
 public:
  virtual ~HistoryColumns() = default;
  virtual std::vector<std::string> columns() const = 0;
  // Appends one value per column, for the solver's current state.
  virtual void values(const solver::Solver& solver, std::vector<double>& row) const = 0;
};

class HistoryWriter : public RunObserver {
 public:
  using Clock = std::chrono::steady_clock;
  // Longest wall time a computed row waits before it is appended to the file.
  static constexpr std::chrono::milliseconds kAppendDelay{1000};

  // Rows every `interval` s; `extra` sources add their columns after the solver's (coupon probe).
  HistoryWriter(const model::Model& model, std::filesystem::path file, double interval,
                std::vector<const HistoryColumns*> extra = {});

  void start(const solver::Solver& solver) override;
  void resume(const solver::Solver& solver) override;
  void after_cycle(const solver::Solver& solver) override;
  std::string_view timing_name() const override { return "history (CSV)"; }
  void stop(const solver::Solver* solver, RunReport& report) override;
  void visit_state(StateVisitor& visitor) override;

 private:
  void add_row(const solver::Solver& solver);
  // Atomic rewrite of the whole table, then appends continue on the new file.
  void rewrite(bool keep_appending);
  void append_pending();

  const model::Model& model_;
  std::filesystem::path file_;
  std::vector<const HistoryColumns*> extra_;
  std::optional<output::HistoryTable> table_;  // columns known once the solver is built
  std::vector<double> row_;
  std::vector<double> stored_;  // the table's values passing through visit_state
  Sampler rows_;
  output::AppendingFile appender_;
  std::size_t rows_on_disk_ = 0;
  Clock::time_point last_append_;
};

}  // namespace plyimpact::run
