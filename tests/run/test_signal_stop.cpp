// A stop by signal ends a run like an early stop. `plyimpact run` is started as a child process on
// a scene far too long to finish (the tiebreak plate of restart_scenes.hpp run for 1 s of simulated
// time); once history.csv holds rows beyond t = 0 (rows reach the disk while the run goes, at most
// HistoryWriter::kAppendDelay after they are computed, and the file is a valid CSV at that moment),
// it gets SIGTERM (and, in a second test, SIGINT as from Ctrl-C) and must: exit with code 2, write
// summary.json with status "interrupted" naming the signal, a frame at the time it stopped (the
// .pvd's last entry, equal to the summary's end time), a complete history (a valid CSV whose rows
// run without gap up to the stop: the last row lies within about one history interval of the end)
// and a restart dump; and leave no temporary behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "core/error.hpp"
#include "output/history_table.hpp"
#include "restart_scenes.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

// Starts `plyimpact run scene -o dir` with its output sent to dir/../log.txt.
pid_t start_run(const fs::path& scene, const fs::path& dir) {
  const std::string binary = PLYIMPACT_BINARY_DIR "/src/app/plyimpact";
  const std::string log = (dir.parent_path() / "log.txt").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen(log.c_str(), "w", stdout);
    std::freopen(log.c_str(), "a", stderr);
    ::execl(binary.c_str(), binary.c_str(), "run", scene.c_str(), "-o", dir.c_str(), "--threads", "1",
            static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  return pid;
}

// Rows in history.csv now (0 while the file does not exist); the file must parse at any moment.
std::size_t history_rows(const fs::path& file) {
  if (!fs::exists(file)) return 0;
  return output::read_history_csv(file).rows();
}

void expect_clean_stop(int signal, const std::string& signal_name) {
  test::TestDir tmp;
  const fs::path scene = test::write_file(tmp / "long.yaml", test::kTiebreakScene);
  const fs::path dir = tmp / "out";
  // Long enough never to finish here; the history interval keeps rows coming every few cycles.
  std::string yaml = test::kTiebreakScene;
  yaml.replace(yaml.find("termination_time: 3.0e-6"), 24, "termination_time: 1.0");
  yaml.replace(yaml.find("{interval: 1.0e-6, history_interval: 5.0e-8}"), 44,
               "{interval: 1.0e-6, history_interval: 1.0e-7}");
  test::write_file(scene, yaml);
  const pid_t pid = start_run(scene, dir);
  ASSERT_GT(pid, 0);

  // Rows beyond the one at t = 0 appear while the run goes (within about a second of wall time).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::size_t rows = 0;
  while ((rows = history_rows(dir / "history.csv")) < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_GE(rows, 3u) << "history rows did not reach the disk while the run was going";
  ::kill(pid, signal);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping cleanly\n"
                                 << test::read_file(tmp / "log.txt");
  EXPECT_EQ(WEXITSTATUS(status), 2) << test::read_file(tmp / "log.txt");

  const std::string summary = test::read_file(dir / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("interrupted by " + signal_name), std::string::npos) << summary;
  const double end_time = test::json_number(summary, "end_time");
  ASSERT_GT(end_time, 0);
  ASSERT_LT(end_time, 1.0);

  // The frame of the stop: the .pvd's last entry at the summary's end time (17 digits both).
  const auto frames = test::pvd_frames(dir / "long.pvd");
  ASSERT_GE(frames.size(), 2u);
  EXPECT_TRUE(fs::exists(dir / frames.back()));
  const std::string pvd = test::read_file(dir / "long.pvd");
  const std::size_t last = pvd.rfind("timestep=\"");
  EXPECT_DOUBLE_EQ(std::strtod(pvd.c_str() + last + 10, nullptr), end_time);

  // Complete history: a row for every interval mark up to the stop. A row's time is the energy
  // balance's (t^n of the cycle that reached the mark), up to one step (< 0.1 interval here) early.
  const auto history = output::read_history_csv(dir / "history.csv");
  const double interval = 1.0e-7;
  ASSERT_GE(history.rows(), 3u);
  EXPECT_EQ(history.at(0, 0), 0.0);
  for (std::size_t r = 1; r < history.rows(); ++r) {
    const double gap = history.at(r, 0) - history.at(r - 1, 0);
    ASSERT_GT(gap, 0.5 * interval) << "row " << r;
    ASSERT_LT(gap, 1.5 * interval) << "a row is missing before row " << r;
  }
  const double last_row = history.at(history.rows() - 1, 0);
  EXPECT_LE(last_row, end_time);
  EXPECT_GT(last_row, end_time - 1.5 * interval);

  EXPECT_TRUE(fs::exists(dir / "restart.dump"));
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

TEST(SignalStop, SigtermEndsTheRunLikeAnEarlyStop) { expect_clean_stop(SIGTERM, "SIGTERM"); }

TEST(SignalStop, SigintEndsTheRunLikeAnEarlyStop) { expect_clean_stop(SIGINT, "SIGINT"); }

}  // namespace
}  // namespace plyimpact
