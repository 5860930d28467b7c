// Runs a built model to its termination time and writes the results into one directory:
//   <scene>.pvd + <scene>_NNNN.vtu (frames), history.csv (energies, dt, reactions), summary.json.
// Every file is written atomically and rewritten as the run goes, so a run that stops early keeps
// everything written so far and summary.json says why it stopped.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace plyimpact::solver {

struct RunOptions {
  std::filesystem::path output_dir;
  std::ostream* progress = nullptr;  // progress line; nullptr = silent
  bool progress_in_place = false;    // true on a terminal: one line updated with '\r'
};

struct RunReport {
  bool completed = false;
  std::string stop_reason;       // empty when completed
  long cycles = 0;
  double end_time = 0;
  double wall_seconds = 0;          // whole run including output
  double ns_per_element_cycle = 0;  // solver cycles only
  double energy_ratio = 1;
  std::vector<std::string> warnings;
  std::filesystem::path pvd, history, summary;
};

RunReport run_model(const model::Model& model, const RunOptions& options);

}  // namespace plyimpact::solver
