// Runs a built model to its termination time. The time loop (run_loop) only steps the solver and
// hands it to observers (run/run_observer.hpp); run_model adds the standard ones, which write the
// results into one folder that the run owns (run/output_folder.hpp):
//   <scene>.pvd + <scene>_NNNN.vtu (frames), history.csv (energies, dt, reactions), summary.json,
//   restart.dump (run/restart_dump.hpp).
// Every file is written atomically (history.csv grows by whole rows in between), so a run that
// stops early keeps everything written so far and summary.json says why it stopped. A run ends
// early on SIGINT/SIGTERM (run/stop_signals.hpp) as on max_cycles: the current frame, the history,
// a restart dump and the summary are written. A restart dump is also written every
// output.restart_interval of simulated time and at the end, so a completed run can be extended.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

struct RunOptions {
  std::filesystem::path output_dir;
  std::ostream* progress = nullptr;  // progress line; nullptr = silent
  bool progress_in_place = false;    // true on a terminal: one line updated with '\r'
  std::filesystem::path restart;     // dump to continue from; empty = start at t = 0
  std::uint64_t scene_digest = 0;    // config::scene_digest of the effective scene (dump identity)
  bool replace = false;              // remove another run's results from output_dir first
  bool stop_on_signals = false;      // SIGINT/SIGTERM stop the run cleanly (the command line)
};

struct LoadedDump;  // run/restart_dump.hpp

// What run_loop does besides stepping: continue from a dump, write dumps, watch for a stop signal.
struct LoopOptions {
  const LoadedDump* restart = nullptr;  // continue from it instead of starting at t = 0
  std::filesystem::path dump_file;             // empty = no dumps
  double dump_interval = 0;                    // s; 0 = dumps only at the end
  std::uint64_t identity = 0;                  // written into the dumps
  bool watch_signals = false;                  // check StopSignals::received() once per cycle
};

// Builds the solver and steps it to the termination time (or control.max_cycles, or a stop
// signal), calling the observers in order. A RunError ends the run: the report says why, and stop
// is still called. A dump that does not fit the model throws InputError before anything is written.
RunReport run_loop(const model::Model& model, const std::vector<RunObserver*>& observers,
                   const LoopOptions& options = {});

// run_loop with frames, history, progress, the checks, the summary and the output folder's checks.
RunReport run_model(const model::Model& model, const RunOptions& options);

}  // namespace plyimpact::run
