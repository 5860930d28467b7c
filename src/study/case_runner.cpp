// Child-process scheduling for studies. See case_runner.hpp.
#include "study/case_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <ostream>

extern char** environ;

namespace plyimpact::study {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Starts `program args...` with stdout and stderr to `log`; returns the pid or -1.
pid_t spawn_case(const std::filesystem::path& program, const CaseJob& job, const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<std::string> words{program.string()};
  words.insert(words.end(), job.args.begin(), job.args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

}  // namespace

std::string format_duration(double s) {
  s = std::max(0.0, s);
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1fs", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%dm%02ds", int(s / 60), int(s) % 60);
  else std::snprintf(buf, sizeof buf, "%dh%02dm", int(s / 3600), int(s / 60) % 60);
  return buf;
}

std::vector<CaseOutcome> run_case_processes(const std::filesystem::path& program, const std::vector<CaseJob>& list,
                                            int jobs, std::ostream& progress,
                                            const std::function<void(std::size_t, const CaseOutcome&)>& on_done) {
  std::vector<CaseOutcome> outcomes(list.size());
  std::map<pid_t, std::pair<std::size_t, Clock::time_point>> running;
  const auto t0 = Clock::now();
  const std::size_t n = list.size();
  std::size_t next = 0, done = 0;
  double case_seconds = 0;
  jobs = std::max(1, jobs);
  auto finish = [&](std::size_t i) {
    ++done;
    const CaseOutcome& o = outcomes[i];
    case_seconds += o.seconds;
    const double mean = case_seconds / double(done);
    const double eta = mean * double(n - done) / double(std::min<std::size_t>(std::size_t(jobs), std::max<std::size_t>(1, n - done)));
    progress << "case " << done << " of " << n << " done: " << list[i].name << " ("
             << (o.failure.empty() ? (o.exit_code == 0 ? "completed" : "exit " + std::to_string(o.exit_code)) : o.failure)
             << ", " << format_duration(o.seconds) << "); elapsed " << format_duration(since(t0)) << ", ETA "
             << format_duration(done == n ? 0.0 : eta) << "\n"
             << std::flush;
    on_done(i, o);
  };
  while (done < n) {
    while (next < n && running.size() < std::size_t(jobs)) {
      const CaseJob& job = list[next];
      std::filesystem::create_directories(job.dir);
      const pid_t pid = spawn_case(program, job, job.dir / "run.log");
      progress << "case " << next + 1 << " of " << n << " started: " << job.name << "\n" << std::flush;
      if (pid < 0) {
        outcomes[next].failure = "could not start " + program.string();
        finish(next++);
        continue;
      }
      running[pid] = {next++, Clock::now()};
    }
    if (running.empty()) continue;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;  // no children left (should not happen while `running` is non-empty)
    const auto it = running.find(pid);
    if (it == running.end()) continue;  // a child this runner did not start
    const auto [i, started] = it->second;
    running.erase(it);
    CaseOutcome& o = outcomes[i];
    o.seconds = since(started);
    if (WIFEXITED(status)) o.exit_code = WEXITSTATUS(status);
    else if (WIFSIGNALED(status)) o.failure = "killed by signal " + std::to_string(WTERMSIG(status));
    finish(i);
  }
  return outcomes;
}

}  // namespace plyimpact::study
