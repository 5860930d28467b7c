// history.csv: one row per history interval (energies, step, reactions, contact, wall and rigid-body
// columns, erosion), rewritten atomically at every frame and at the end, so a run that stops early
// keeps its history.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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

// Erosion columns only when something can erode (a material with failure, or erode_tsmin).
bool can_erode(const model::Model& model);

class HistoryWriter : public RunObserver {
 public:
  // Rows every `interval` s; the file is rewritten every `flush_interval` s and on the last cycle.
  HistoryWriter(const model::Model& model, std::filesystem::path file, double interval, double flush_interval,
                std::vector<const HistoryColumns*> extra = {});

  void start(const solver::Solver& solver) override;
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;

 private:
  void add_row(const solver::Solver& solver);

  const model::Model& model_;
  std::filesystem::path file_;
  std::vector<const HistoryColumns*> extra_;
  double t_end_;
  std::optional<output::HistoryTable> table_;  // columns known once the solver is built
  std::vector<double> row_;
  Sampler rows_, flushes_;
};

}  // namespace plyimpact::run
