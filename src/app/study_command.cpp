// study: argument parsing onto study::StudyOptions. See study_command.hpp.
#include "app/study_command.hpp"

#include <charconv>
#include <iostream>

#include "study/quantities.hpp"
#include "study/study.hpp"
#include "study/study_spec.hpp"

namespace plyimpact::app {

const char* const kStudyUsage =
    "  study STUDY.yaml [-j N] [--threads T] [-o DIR] [--dry-run | --collect | --emit slurm|parallel]\n"
    "                            run every case of a parameter or mesh-convergence study (each a child\n"
    "                            `plyimpact run`, N at a time, T threads each, N x T <= cores), reusing\n"
    "                            finished cases of the same scene; writes study.csv, study.json and plots\n"
    "                            (configs/studies/ has examples). --dry-run lists the cases, --emit\n"
    "                            writes the pending ones as a Slurm job array or GNU parallel job list,\n"
    "                            --collect gathers the finished case folders into the table; a study with\n"
    "                            ballistic_limit: then brackets the perforation velocity round by round\n";

namespace {

bool parse_count(const std::string& text, int& value) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && value > 0;
}

int bad_usage(std::ostream& err, const std::string& why) {
  err << "plyimpact study: " << why << "\nusage:\n" << kStudyUsage << "quantities:";
  for (const auto& q : study::quantity_table()) err << " " << q.name;
  err << "\n";
  return 64;
}

}  // namespace

int study_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  study::StudyOptions options;
  std::string file;
  int modes = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    if ((a == "-j" || a == "--jobs") && has_value) {
      if (!parse_count(args[++i], options.jobs)) return bad_usage(err, "-j needs a positive number, found '" + args[i] + "'");
    } else if (a == "--threads" && has_value) {
      if (!parse_count(args[++i], options.threads))
        return bad_usage(err, "--threads needs a positive number, found '" + args[i] + "'");
    } else if ((a == "-o" || a == "--output") && has_value) {
      options.output_dir = args[++i];
    } else if (a == "--dry-run") {
      options.dry_run = true;
      ++modes;
    } else if (a == "--collect") {
      options.collect = true;
      ++modes;
    } else if (a == "--emit" && has_value) {
      const std::string& what = args[++i];
      if (what != "slurm" && what != "parallel") return bad_usage(err, "--emit takes slurm or parallel, found '" + what + "'");
      options.emit = what == "slurm" ? study::Emit::slurm : study::Emit::parallel;
      ++modes;
    } else if (file.empty() && !a.starts_with("-")) {
      file = a;
    } else {
      return bad_usage(err, "unexpected argument '" + a + "'");
    }
  }
  if (file.empty()) return bad_usage(err, "needs a study file");
  if (modes > 1) return bad_usage(err, "--dry-run, --collect and --emit exclude each other");
  const study::StudySpec spec = study::read_study(file);
  const study::StudyOutcome r = study::run_study(spec, options, out);
  if (options.dry_run || options.emit != study::Emit::none) return 0;
  return r.failed > 0 || r.pending > 0 || !r.errors.empty() ? 2 : 0;
}

}  // namespace plyimpact::app
