// Hand-off of a study's pending cases to the scheduler a user already has, instead of a home-made
// distributor: a Slurm job array (sbatch slurm_array.sh; one array task per case, reading its
// command line from pending_cases.txt) or a GNU parallel job list (parallel -j N < parallel_jobs.txt).
// Each line is the full `plyimpact run ...` command of one case, its console output going to the
// case's run.log; `plyimpact study STUDY.yaml --collect` then gathers the finished folders.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact::study {

struct PendingCase {
  std::string name;
  std::filesystem::path dir;
  std::vector<std::string> args;  // after the program
};

/// One shell command per case: '<program>' 'arg' ... > '<dir>/run.log' 2>&1
std::vector<std::string> case_command_lines(const std::filesystem::path& program, const std::vector<PendingCase>& cases);

/// Writes <dir>/pending_cases.txt and <dir>/slurm_array.sh (atomically); returns the script path.
std::filesystem::path write_slurm_array(const std::filesystem::path& dir, const std::string& study_name,
                                        const std::vector<std::string>& commands, int threads_per_case);

/// Writes <dir>/parallel_jobs.txt; returns its path.
std::filesystem::path write_parallel_jobs(const std::filesystem::path& dir, const std::vector<std::string>& commands);

/// POSIX shell single-quoting.
std::string shell_quote(const std::string& word);

}  // namespace plyimpact::study
