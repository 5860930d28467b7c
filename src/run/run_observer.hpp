// The run loop hands the solver to observers: everything that watches a run without changing its
// physics (frames, history, summary, progress line, energy and hourglass checks; a study runner
// later) is one. The loop calls start once the solver is built (the state at t = 0), after_cycle
// after every cycle, and stop once, also when the run stopped with an error (then `solver` may be
// null: it could not be built). Observers see the solver read-only.
// A run continued from a restart dump (run/restart_dump.hpp) calls visit_state with the dump's
// reader and then resume instead of start: what an observer has gathered so far (history rows,
// frame times, the samplers' next marks, a check's extremes) is part of the run state, so a
// continued run writes the same files as one that never stopped.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/state_visitor.hpp"
#include "run/energy_balance_watch.hpp"
#include "run/hourglass_watch.hpp"
#include "run/run_timing.hpp"
#include "solver/solver.hpp"

namespace plyimpact::run {

// Delaminated areas at the stop (tiebreak or other delaminating interfaces), for summary.json.
struct DelaminationReport {
  struct Interface {
    int id = 0;
    std::string label;        // "interface_3 (plies 3/4, 45/-45)"
    double depth = 0;         // m below the impacted face
    double area = 0;          // m^2 separated (damage 1)
  };
  std::vector<Interface> interfaces;
  double total_area = 0;      // m^2, sum over the interfaces
  double projected_area = 0;  // m^2, union of their projections on the plate plane (the C-scan)
  double cscan_pitch = 0;     // m, raster cell side of the C-scan
};

struct RunReport {
  bool completed = false;
  bool interrupted = false;      // stopped by SIGINT or SIGTERM (the state is sound)
  bool failed = false;           // stopped by a RunError (the state may not be sound)
  std::string stop_reason;       // empty when completed
  std::string termination;       // a termination rule that ended the run before termination_time (completed)
  long cycles = 0;
  double end_time = 0;
  double wall_seconds = 0;          // whole run including output
  double ns_per_element_cycle = 0;  // solver cycles only
  double energy_ratio = 1;
  std::vector<std::string> warnings;
  std::filesystem::path pvd, history, summary, dump;
  std::filesystem::path interfaces_pvd, cscan_vtu, cscan_png;  // empty when not written
  std::optional<DelaminationReport> delamination;               // scenes with delaminating interfaces
  std::optional<HourglassVerdict> hourglass;                    // the hourglass check (HourglassCheck)
  std::optional<EnergyBalanceVerdict> energy_balance;           // the energy check (EnergyBalanceCheck)
  RunTiming timing;                                             // where the wall time went (run_timing.hpp)
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void start(const solver::Solver& solver) { (void)solver; }
  // Instead of start when the run continues from a dump, after visit_state has read it.
  virtual void resume(const solver::Solver& solver) { (void)solver; }
  // The observer's share of the run state (nothing for a stateless observer).
  virtual void visit_state(StateVisitor& visitor) { (void)visitor; }
  virtual void after_cycle(const solver::Solver& solver) { (void)solver; }
  // Non-empty once the observer's termination rule (a *TERMINATION_ card) is met: the loop then ends
  // the run as completed, with this text as the reason.
  virtual std::string termination() const { return {}; }
  // Its row in the run's timing (observers of one name share a row).
  virtual std::string_view timing_name() const { return "run checks"; }
  // In the order the observers were registered: a later one sees the warnings of earlier ones.
  virtual void stop(const solver::Solver* solver, RunReport& report) {
    (void)solver;
    (void)report;
  }
};

// Fires at t = interval, 2 interval, ...; a cycle that jumps over several marks fires once and
// the next mark is the first one after t. The relative slack 1e-12 absorbs the round-off of the
// summed time steps.
class Sampler {
 public:
  explicit Sampler(double interval) : interval_(interval), next_(interval) {}
  bool due(double t) const { return t >= next_ * (1 - 1e-12); }
  void advance(double t) { next_ += interval_ * std::max(1.0, std::floor((t - next_) / interval_) + 1); }
  // The next mark is run state; the interval comes from the scene (it may change on a restart).
  void visit_state(StateVisitor& visitor, std::string_view name) { visitor.scalar(name, next_); }

 private:
  double interval_, next_;
};

}  // namespace plyimpact::run
