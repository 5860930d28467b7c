// Slurm and GNU parallel job files. See scheduler_scripts.hpp.
#include "study/scheduler_scripts.hpp"

#include "output/atomic_file.hpp"

namespace plyimpact::study {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& word) {
  std::string out(1, '\'');
  for (char c : word) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  out += '\'';
  return out;
}

std::vector<std::string> case_command_lines(const fs::path& program, const std::vector<PendingCase>& cases) {
  std::vector<std::string> lines;
  for (const auto& c : cases) {
    std::string line = shell_quote(program.string());
    for (const auto& a : c.args) {
      line += ' ';
      line += shell_quote(a);
    }
    line += " > ";
    line += shell_quote((fs::absolute(c.dir) / "run.log").string());
    line += " 2>&1";
    lines.push_back(std::move(line));
  }
  return lines;
}

fs::path write_slurm_array(const fs::path& dir, const std::string& study_name, const std::vector<std::string>& commands,
                           int threads_per_case) {
  fs::create_directories(dir);
  const fs::path list = fs::absolute(dir) / "pending_cases.txt";
  std::string text;
  for (const auto& c : commands) text += c + "\n";
  output::write_text_atomically(list, text);
  std::string script =
      "#!/bin/bash\n"
      "# Slurm job array: one task per pending case of the study; each task runs line\n"
      "# $SLURM_ARRAY_TASK_ID of pending_cases.txt. Submit with: sbatch " +
      (fs::absolute(dir) / "slurm_array.sh").string() +
      "\n# then gather the results with: plyimpact study <study file> --collect\n"
      "#SBATCH --job-name=plyimpact-" + study_name + "\n"
      "#SBATCH --array=1-" + std::to_string(commands.size()) + "\n"
      "#SBATCH --ntasks=1\n"
      "#SBATCH --cpus-per-task=" + std::to_string(threads_per_case) + "\n"
      "#SBATCH --output=" + (fs::absolute(dir) / "slurm-%A_%a.out").string() + "\n"
      "set -euo pipefail\n"
      "export OMP_NUM_THREADS=" + std::to_string(threads_per_case) + "\n"
      "command=$(sed -n \"${SLURM_ARRAY_TASK_ID}p\" " + shell_quote(list.string()) + ")\n"
      "eval \"$command\"\n";
  const fs::path path = dir / "slurm_array.sh";
  output::write_text_atomically(path, script);
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  return path;
}

fs::path write_parallel_jobs(const fs::path& dir, const std::vector<std::string>& commands) {
  fs::create_directories(dir);
  std::string text;
  for (const auto& c : commands) text += c + "\n";
  const fs::path path = dir / "parallel_jobs.txt";
  output::write_text_atomically(path, text);
  return path;
}

}  // namespace plyimpact::study
