// Case batches. See case_batch.hpp.
#include "study/case_batch.hpp"

#include <ostream>

#include "study/case_runner.hpp"

namespace plyimpact::study {

std::vector<std::string> run_case_batch(const CaseBatch& b, const std::vector<Case>& cases, std::ostream& out) {
  std::vector<CaseJob> list;
  for (const Case& c : cases) {
    const auto dir = b.dir / c.name;
    std::error_code ec;
    std::filesystem::remove(dir / "summary.json", ec);  // a stale result must not count as this case's
    write_case_record(*b.spec, c, dir, "running");
    list.push_back({c.name, dir, case_arguments(*b.spec, c, dir, b.threads)});
  }
  std::vector<std::string> failures(cases.size());
  run_case_processes(b.program, list, b.jobs, out, [&](std::size_t i, const CaseOutcome& oc) {
    const auto dir = b.dir / cases[i].name;
    // Exit 0 completed, 2 stopped early with its summary written: both are results.
    if (oc.failure.empty() && (oc.exit_code == 0 || oc.exit_code == 2) && std::filesystem::exists(dir / "summary.json")) {
      write_case_record(*b.spec, cases[i], dir, oc.exit_code == 0 ? "completed" : "stopped");
    } else {
      failures[i] = oc.failure.empty() ? "exit code " + std::to_string(oc.exit_code) : oc.failure;
      write_case_record(*b.spec, cases[i], dir, "failed: " + failures[i]);
    }
  });
  return failures;
}

}  // namespace plyimpact::study
