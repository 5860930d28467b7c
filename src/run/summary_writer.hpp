// summary.json: how the run ended and why, its size and cost, the subsystems it used, the final
// energies, warnings, erosion by part and cause, and the names of the other files. Written once
// at the stop, after every other observer has added its warnings.
#pragma once

#include <chrono>
#include <filesystem>

#include "run/run_observer.hpp"

namespace plyimpact::run {

class SummaryWriter : public RunObserver {
 public:
  using Clock = std::chrono::steady_clock;
  SummaryWriter(const model::Model& model, std::filesystem::path file, Clock::time_point t_start)
      : model_(model), file_(std::move(file)), t_start_(t_start) {}
  void stop(const solver::Solver* solver, RunReport& report) override;

 private:
  const model::Model& model_;
  std::filesystem::path file_;
  Clock::time_point t_start_;
};

}  // namespace plyimpact::run
