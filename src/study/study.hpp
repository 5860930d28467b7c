// `plyimpact study`: validates every case's effective scene in-process (errors name the study
// file line of the value), skips the cases whose folder already holds a finished run of the same
// effective scene, runs the others as child processes side by side (total threads <= cores),
// then runs the ballistic-limit search when the study asks for one (ballistic_study.hpp), and
// writes study.csv, study.json, the convergence, Lambert-Jonas and ballistic-limit results and
// the plots, all atomically. Alternatively writes the pending cases for Slurm or GNU parallel
// (emit), or only gathers the finished folders (collect), or only lists the cases (dry run).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "study/study_spec.hpp"

namespace plyimpact::study {

enum class Emit { none, slurm, parallel };

struct StudyOptions {
  int jobs = 1;                       // cases at once
  int threads = 0;                    // per case; 0: the study file's, else cores / jobs
  int cores = 0;                      // 0: std::thread::hardware_concurrency()
  std::filesystem::path output_dir;   // empty: the study file's
  bool dry_run = false, collect = false;
  Emit emit = Emit::none;
  std::filesystem::path program;      // the plyimpact executable the cases run
};

struct StudyOutcome {
  std::size_t cases = 0, already_finished = 0, ran = 0, failed = 0, pending = 0;
  std::filesystem::path dir;
  std::vector<std::string> warnings;
  std::vector<std::string> errors;  // a ballistic-limit search that ended without a limit, and why
};

/// Runs (or emits, collects, lists) the study. @throws InputError for an invalid case
StudyOutcome run_study(const StudySpec& spec, const StudyOptions& options, std::ostream& out);

}  // namespace plyimpact::study
