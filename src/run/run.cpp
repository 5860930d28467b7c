#include "run/run.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>

#include "core/error.hpp"
#include "run/contact_termination.hpp"
#include "run/coupon_probe.hpp"
#include "run/frame_writer.hpp"
#include "run/history_writer.hpp"
#include "run/output_folder.hpp"
#include "run/interface_frame_writer.hpp"
#include "run/progress_line.hpp"
#include "run/restart_dump.hpp"
#include "run/run_checks.hpp"
#include "run/stop_signals.hpp"
#include "run/summary_writer.hpp"
#include "solver/solver.hpp"

namespace plyimpact::run {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The solver's phases in the cycles (their times less those of the set-up's first force pass,
// phases_at_start), then its bookkeeping outside them (the step, the energy sums), then each
// observer's row; solver_seconds: wall time inside Solver::step.
void add_cycle_rows(RunTiming& timing, const solver::Solver* solver, const std::vector<double>& phases_at_start,
                    double solver_seconds, const std::vector<RunObserver*>& observers,
                    const std::vector<double>& observer_seconds) {
  double phases = 0;
  if (solver)
    for (std::size_t k = 0; k < solver->phase_times().size(); ++k) {
      const auto& p = solver->phase_times()[k];
      const double s = p.seconds - (k < phases_at_start.size() ? phases_at_start[k] : 0.0);
      timing.add(p.name, s);
      phases += s;
    }
  timing.add("solver, outside the phases", std::max(0.0, solver_seconds - phases));
  for (std::size_t k = 0; k < observers.size(); ++k) timing.add(observers[k]->timing_name(), observer_seconds[k]);
}
}  // namespace

RunReport run_loop(const model::Model& model, const std::vector<RunObserver*>& observers, const LoopOptions& options) {
  if (model.control.threads > 0) omp_set_num_threads(model.control.threads);
  RunReport report;
  const double t_end = model.control.termination_time;
  double solver_seconds = 0, dump_seconds = 0;
  std::vector<double> observer_seconds(observers.size(), 0.0), phases_at_start;
  long solver_cycles = 0;
  std::unique_ptr<solver::Solver> solver;
  const auto t_loop = Clock::now();
  const auto dump = [&] {
    const auto t0 = Clock::now();
    write_dump(options.dump_file, options.identity, *solver, observers);
    report.dump = options.dump_file;
    dump_seconds += seconds_since(t0);
  };
  try {
    solver = std::make_unique<solver::Solver>(model);
    solver->choose_threads_by_timing(model.control.threads == 0);  // --threads N fixes the count
    for (const auto& w : solver->warnings()) report.warnings.push_back(w);
    if (options.restart) {
      read_dump(*options.restart, *solver, observers);
      for (RunObserver* o : observers) o->resume(*solver);
    } else {
      for (RunObserver* o : observers) o->start(*solver);
    }
    report.timing.add("set-up (solver, first output)", seconds_since(t_loop));
    for (const auto& p : solver->phase_times()) phases_at_start.push_back(p.seconds);
    // Dumps do not change the run, so their schedule is not run state: the next mark after now.
    Sampler dumps(options.dump_interval > 0 ? options.dump_interval : std::numeric_limits<double>::infinity());
    if (dumps.due(solver->state().time)) dumps.advance(solver->state().time);
    const long max_cycles = model.control.max_cycles;
    while (solver->state().time < t_end * (1 - 1e-12) && (max_cycles <= 0 || solver->state().cycle < max_cycles)) {
      if (options.watch_signals && StopSignals::received() != 0) {
        report.interrupted = true;
        report.stop_reason = "interrupted by " + StopSignals::name(StopSignals::received());
        break;
      }
      solver::State& s = solver->state();
      if (s.time + s.dt_next_half > t_end) s.dt_next_half = t_end - s.time;  // land on the end time
      const auto t0 = Clock::now();
      solver->step();
      solver_seconds += seconds_since(t0);
      ++solver_cycles;
      for (std::size_t k = 0; k < observers.size(); ++k) {
        const auto t1 = Clock::now();
        observers[k]->after_cycle(*solver);
        observer_seconds[k] += seconds_since(t1);
        if (report.termination.empty()) report.termination = observers[k]->termination();
      }
      if (!options.dump_file.empty() && dumps.due(solver->state().time)) {
        dump();
        dumps.advance(solver->state().time);
      }
      if (!report.termination.empty()) break;
    }
    report.completed = solver->state().time >= t_end * (1 - 1e-12) || !report.termination.empty();
    if (!report.completed && !report.interrupted) report.stop_reason = "max_cycles reached before the termination time";
    // Before the observers' stop: the frame an early stop writes is not part of the run state.
    if (!options.dump_file.empty()) dump();
  } catch (const RunError& e) {
    report.completed = false;
    report.failed = true;
    report.stop_reason = e.what();
  }
  if (solver) {
    report.cycles = solver->state().cycle;
    report.end_time = solver->state().time;
    report.energy_ratio = solver->energy_ratio();
  }
  add_cycle_rows(report.timing, solver.get(), phases_at_start, solver_seconds, observers, observer_seconds);
  if (dump_seconds > 0) report.timing.add("restart dumps", dump_seconds);
  report.timing.span = seconds_since(t_loop);
  const double element_cycles = double(model.num_elements()) * double(solver_cycles);
  report.ns_per_element_cycle = element_cycles > 0 ? 1e9 * solver_seconds / element_cycles : 0.0;
  for (RunObserver* o : observers) o->stop(solver.get(), report);
  return report;
}

RunReport run_model(const model::Model& model, const RunOptions& options) {
  const auto t_start = Clock::now();
  const std::uint64_t identity = run_identity(options.scene_digest, model);
  std::optional<LoadedDump> restart;
  if (!options.restart.empty()) restart = load_dump(options.restart, identity);  // refused before any write
  prepare_output_folder(options.output_dir, model.name, identity, FolderUse{restart.has_value(), options.replace});
  const OutputFolderGuard guard(options.output_dir);

  const double t_end = model.control.termination_time;
  const double frame_interval = model.output.interval > 0 ? model.output.interval : t_end / 20;
  const double history_interval = model.output.history_interval > 0 ? model.output.history_interval : t_end / 1000;

  std::optional<CouponProbe> coupon;
  if (model.coupon) coupon.emplace(model);
  HistoryWriter history(model, options.output_dir / "history.csv", history_interval,
                        coupon ? std::vector<const HistoryColumns*>{&*coupon} : std::vector<const HistoryColumns*>{});
  FrameWriter frames(model, options.output_dir, frame_interval);
  InterfaceFrameWriter interfaces(model, options.output_dir, frame_interval);
  HourglassCheck hourglass(model, history_interval, model.control.hourglass_warn_ratio);
  ContactEnergyCheck contact_energy(model);
  ContactPenetrationCheck penetrations(options.progress);
  EnergyBalanceCheck energy_balance(history_interval);
  SummaryWriter summary(model, options.output_dir / "summary.json", t_start);
  std::unique_ptr<ProgressLine> progress;
  if (options.progress) progress = std::make_unique<ProgressLine>(*options.progress, options.progress_in_place, t_end, t_start);

  // Stop order is the order of the warnings in summary.json; the summary comes last.
  std::optional<ContactTermination> termination;
  if (model.control.termination_contact) termination.emplace(*model.control.termination_contact);
  std::vector<RunObserver*> observers = {&frames, &interfaces, &history};
  if (termination) observers.push_back(&*termination);
  if (progress) observers.push_back(progress.get());
  for (RunObserver* o : std::initializer_list<RunObserver*>{&hourglass, &contact_energy, &penetrations, &energy_balance, &summary})
    observers.push_back(o);

  LoopOptions loop;
  loop.restart = restart ? &*restart : nullptr;
  loop.dump_file = options.output_dir / kDumpFileName;
  loop.dump_interval = model.output.restart_interval;
  loop.identity = identity;
  loop.watch_signals = options.stop_on_signals;
  std::optional<StopSignals> signals;
  if (options.stop_on_signals) signals.emplace();
  RunReport report = run_loop(model, observers, loop);
  report.wall_seconds = seconds_since(t_start);
  return report;
}

}  // namespace plyimpact::run
