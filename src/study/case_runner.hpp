// Runs study cases as child processes (`plyimpact run ...`), up to `jobs` at a time, so a case that
// crashes or is killed ends only itself. Each child writes its console output to <case>/run.log.
// Progress goes to `progress`: one line per case started and finished, with "case k of n", the
// elapsed time and an ETA (mean case time x cases left / jobs, never negative).
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace plyimpact::study {

struct CaseJob {
  std::string name;
  std::filesystem::path dir;       // created if missing; run.log goes here
  std::vector<std::string> args;   // arguments after the program
};

struct CaseOutcome {
  int exit_code = -1;   // the child's exit status; -1 when it died of a signal or could not start
  std::string failure;  // "" or what went wrong ("killed by signal 9", "could not start ...")
  double seconds = 0;
};

/// Runs every job with `program`, at most `jobs` at once; `on_done(i, outcome)` is called as job i
/// ends (in completion order). Returns the outcomes in job order.
std::vector<CaseOutcome> run_case_processes(const std::filesystem::path& program, const std::vector<CaseJob>& list,
                                            int jobs, std::ostream& progress,
                                            const std::function<void(std::size_t, const CaseOutcome&)>& on_done);

/// "12.3s", "4m05s", "2h03m".
std::string format_duration(double seconds);

}  // namespace plyimpact::study
