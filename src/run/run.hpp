// Runs a built model to its termination time. The time loop (run_loop) only steps the solver and
// hands it to observers (run/run_observer.hpp); run_model adds the standard ones, which write the
// results into one directory:
//   <scene>.pvd + <scene>_NNNN.vtu (frames), history.csv (energies, dt, reactions), summary.json;
//   with delaminating interfaces also interfaces.pvd (their surface series) and the C-scan map
//   cscan.vtu + cscan.png (run/interface_frame_writer.hpp).
// Every file is written atomically and rewritten as the run goes, so a run that stops early keeps
// everything written so far and summary.json says why it stopped.
#pragma once

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
};

// Builds the solver and steps it to the termination time (or control.max_cycles), calling the
// observers in order. A RunError ends the run: the report says why, and stop is still called.
RunReport run_loop(const model::Model& model, const std::vector<RunObserver*>& observers);

// run_loop with frames, history, progress, the checks and the summary.
RunReport run_model(const model::Model& model, const RunOptions& options);

}  // namespace plyimpact::run
