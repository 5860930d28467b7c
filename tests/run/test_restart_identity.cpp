// Restart identity through the command line: a run stopped at an arbitrary cycle and continued
// from its restart dump (`plyimpact run SCENE --restart DUMP`) writes, byte for byte, the same
// history.csv, .pvd and final frame as the run that never stopped. The reference is that
// uninterrupted run (one thread); the split runs use one and two threads, so the test also holds
// the results to thread-count independence. Bitwise equality is the only right tolerance: the
// continued run repeats the same arithmetic on the same values, and any piece of state the dump
// forgets (a contact spring, an eroded element, a damage flag, a rigid body's rotation, an
// interface pair, an observer's sampler) shows up as a difference.
// Scenes (restart_scenes.hpp): an eroding impact on a *MAT_054 plate by a rigid sphere, split
// after erosion has begun with the contact active; a plate with a tiebreak interface.
// Also: a completed run extended with a later termination time continues its history and frame
// numbering; dumps are written at the first cycle past every output.restart_interval mark and at
// the end.
#include <gtest/gtest.h>

#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "output/history_table.hpp"
#include "restart_scenes.hpp"
#include "run/restart_dump.hpp"
#include "run/run.hpp"

namespace plyimpact {
namespace {

using test::plyimpact;
namespace fs = std::filesystem;

struct Run {
  fs::path dir;
  std::string history, pvd, last_frame, summary;
};

Run read_run(const fs::path& dir, const std::string& name) {
  Run r{dir, test::read_file(dir / "history.csv"), test::read_file(dir / (name + ".pvd")), "",
        test::read_file(dir / "summary.json")};
  const auto frames = test::pvd_frames(dir / (name + ".pvd"));
  if (!frames.empty()) r.last_frame = test::read_file(dir / frames.back());
  return r;
}

// Runs the scene uninterrupted and split at `split_fraction` of its cycles with `threads`, and
// compares the results.
void expect_split_identical(const test::TestDir& tmp, const std::string& name, const char* yaml, double split_fraction,
                            bool expect_erosion) {
  const fs::path scene = test::write_file(tmp / (name + ".yaml"), yaml);
  const auto whole = plyimpact({"run", scene.string(), "-o", (tmp / "whole").string(), "--threads", "1"});
  ASSERT_EQ(whole.code, 0) << whole.out << whole.err;
  const Run reference = read_run(tmp / "whole", name);
  const long cycles = long(test::json_number(reference.summary, "cycles"));
  const long split = long(split_fraction * double(cycles));
  ASSERT_GT(split, 0);
  ASSERT_LT(split, cycles);

  for (const std::string threads : {"1", "2"}) {
    const fs::path dir = tmp / ("split_" + threads);
    const auto first = plyimpact({"run", scene.string(), "-o", dir.string(), "--threads", threads, "--set",
                                  "control.max_cycles=" + std::to_string(split)});
    ASSERT_EQ(first.code, 2) << "a max_cycles stop exits 2\n" << first.out << first.err;
    const std::string stopped = test::read_file(dir / "summary.json");
    ASSERT_EQ(long(test::json_number(stopped, "cycles")), split);
    if (expect_erosion) {
      ASSERT_GT(test::json_number(stopped, "eroded_elements"), 0) << "split before any erosion";
    }
    ASSERT_TRUE(fs::exists(dir / "restart.dump"));

    const auto second = plyimpact({"run", scene.string(), "-o", dir.string(), "--threads", threads, "--restart",
                                   (dir / "restart.dump").string()});
    ASSERT_EQ(second.code, 0) << second.out << second.err;
    const Run continued = read_run(dir, name);
    EXPECT_EQ(long(test::json_number(continued.summary, "cycles")), cycles) << threads << " threads";
    EXPECT_TRUE(continued.history == reference.history) << "history.csv differs, " << threads << " threads";
    EXPECT_TRUE(continued.pvd == reference.pvd) << "the .pvd differs, " << threads << " threads";
    EXPECT_FALSE(continued.last_frame.empty());
    EXPECT_TRUE(continued.last_frame == reference.last_frame) << "final frame differs, " << threads << " threads";
  }
}

TEST(RestartIdentity, ErodingImpactOnMat054PlateWithRigidSphere) {
  test::TestDir tmp;
  expect_split_identical(tmp, "impact", test::kImpactScene, 0.6, true);
}

// The same impact with erosion neighbourhoods (erosion_nonlocal over 3 mm on the 1 mm elements):
// the two strain buffers carry across the restart (which one the next pass reads follows the
// cycle's parity).
// Also the case of a contact surface that erosion has grown since the run began: at the split the
// eroding contact has about 600 nodes against 460 at construction, more than its 256-node outcome
// chunks held then (a continued run that kept the constructed chunks skipped the nodes beyond them).
TEST(RestartIdentity, ErodingImpactWithErosionNeighbourhoods) {
  test::TestDir tmp;
  std::string yaml = test::kImpactScene;
  const std::string after = "    DFAILS: 0.03\n";
  yaml.insert(yaml.find(after) + after.size(), "    erosion_reference_length: 3\n    erosion_nonlocal: true\n");
  expect_split_identical(tmp, "nonlocal", yaml.c_str(), 0.6, true);
}

TEST(RestartIdentity, PlateWithTiebreakInterface) {
  test::TestDir tmp;
  expect_split_identical(tmp, "tiebreak", test::kTiebreakScene, 0.45, false);
}

// Two runs of the same scene write the same restart dump, byte for byte: every byte of the run
// state is defined (structs written whole carry no padding of indeterminate value), so a dump can
// be compared, hashed or partitioned as data. The eroding impact has contact penetrations (whose
// records once held padding), springs, erosion and a rigid body.
TEST(RestartIdentity, TwoRunsWriteTheSameDumpByteForByte) {
  const test::TestDir tmp;
  const fs::path scene = test::write_file(tmp / "impact.yaml", test::kImpactScene);
  for (const std::string run : {"a", "b"}) {
    const auto r = plyimpact({"run", scene.string(), "-o", (tmp / run).string(), "--threads", "1"});
    ASSERT_EQ(r.code, 0) << r.out << r.err;
  }
  const std::string a = test::read_file(tmp / "a" / "restart.dump"), b = test::read_file(tmp / "b" / "restart.dump");
  ASSERT_FALSE(a.empty());
  EXPECT_GT(test::json_number(test::read_file(tmp / "a" / "summary.json"), "count"), 0.0)
      << "no penetration recorded: the scene no longer exercises the penetration records";
  EXPECT_TRUE(a == b) << "the dumps differ first at byte "
                      << std::distance(a.begin(), std::mismatch(a.begin(), a.end(), b.begin(), b.end()).first);
}

TEST(RestartIdentity, CompletedRunIsExtendedWithALaterTerminationTime) {
  test::TestDir tmp;
  const fs::path scene = test::write_file(tmp / "ext.yaml", test::kTiebreakScene);
  const std::string dir = (tmp / "out").string();
  ASSERT_EQ(plyimpact({"run", scene.string(), "-o", dir, "--set", "control.termination_time=2.0e-6"}).code, 0);
  // The bodies' frames (the .pvd lists the rigid block's file beside each of them).
  const auto body_frames = [&] {
    std::vector<std::string> f;
    for (const auto& file : test::pvd_frames(tmp / "out" / "ext.pvd"))
      if (file.find("_rigid_") == std::string::npos) f.push_back(file);
    return f;
  };
  const auto frames_before = body_frames();
  const auto rows_before = output::read_history_csv(tmp / "out" / "history.csv").rows();
  const auto more = plyimpact({"run", scene.string(), "-o", dir, "--restart", dir + "/restart.dump"});
  ASSERT_EQ(more.code, 0) << more.out << more.err;
  const auto frames_after = body_frames();
  ASSERT_GT(frames_after.size(), frames_before.size());
  for (std::size_t i = 0; i < frames_before.size(); ++i) EXPECT_EQ(frames_after[i], frames_before[i]);
  EXPECT_EQ(frames_after.back(), "ext_" + std::string(4 - std::to_string(frames_after.size() - 1).size(), '0') +
                                     std::to_string(frames_after.size() - 1) + ".vtu");
  const auto history = output::read_history_csv(tmp / "out" / "history.csv");
  EXPECT_GT(history.rows(), rows_before);
  for (std::size_t r = 1; r < history.rows(); ++r) ASSERT_GT(history.at(r, 0), history.at(r - 1, 0)) << "row " << r;
  // Rows carry the balance time, up to one step (< 0.2 interval here) before their mark.
  EXPECT_GT(history.at(history.rows() - 1, 0), 3.0e-6 - 1.5 * 5.0e-8);
}

// Watches restart.dump while the loop runs: the times of the dumps seen, and the first cycle time
// at or past each interval mark.
class DumpWatch : public run::RunObserver {
 public:
  DumpWatch(fs::path file, std::uint64_t identity, double interval)
      : file_(std::move(file)), identity_(identity), interval_(interval) {}
  void after_cycle(const solver::Solver& solver) override {
    const double t = solver.state().time;
    if (t >= (double(expected.size()) + 1) * interval_ * (1 - 1e-12)) expected.push_back(t);
    if (!fs::exists(file_)) return;
    const double dumped = run::load_dump(file_, identity_).info.time;
    if (seen.empty() || seen.back() != dumped) seen.push_back(dumped);
  }
  std::vector<double> seen, expected;

 private:
  fs::path file_;
  std::uint64_t identity_;
  double interval_;
};

TEST(RestartIdentity, DumpsAreWrittenAtTheRestartIntervalAndAtTheEnd) {
  test::TestDir tmp;
  const config::Scene scene = config::load_scene_from_string(test::kTiebreakScene, "dumps.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  run::LoopOptions loop;
  loop.dump_file = tmp / "restart.dump";
  loop.dump_interval = 1.0e-6;
  loop.identity = 42;
  DumpWatch watch(loop.dump_file, loop.identity, loop.dump_interval);
  const run::RunReport report = run::run_loop(model, {&watch}, loop);
  ASSERT_TRUE(report.completed) << report.stop_reason;
  // Marks at 1 and 2 us seen during the run (the one at 3 us is the end: after the last cycle).
  ASSERT_EQ(watch.expected.size(), 3u);
  watch.expected.pop_back();
  EXPECT_EQ(watch.seen, watch.expected);
  const run::LoadedDump last = run::load_dump(loop.dump_file, loop.identity);
  EXPECT_EQ(last.info.time, report.end_time);
  EXPECT_EQ(last.info.cycle, report.cycles);
}

}  // namespace
}  // namespace plyimpact
