// A run owns its output folder (run/output_folder.hpp). Three scenes run in turn with the same -o:
// the second is refused while the first's results are there (exit 1, nothing written, the message
// names the folder, the other scene and --replace); with --replace it removes exactly the first's
// result files — not a file plyimpact does not write — and the folder then holds one run's frames,
// all listed in its .pvd. A rerun of the same scene into its own folder is accepted and leaves no
// frame of the earlier, longer run. Temporaries of dead processes are removed; a run leaves none
// of its own, also when it stops with an error. A restart from a foreign or damaged dump is
// refused before anything is written, naming the file and what differs.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <set>

#include "output/atomic_file.hpp"
#include "restart_scenes.hpp"

namespace plyimpact {
namespace {

using test::plyimpact;
namespace fs = std::filesystem;

const char* kBlock =
    "units: SI\ncontrol: {termination_time: 2.0e-4}\noutput: {interval: 1.0e-5}\nmaterials:\n"
    "  m: {card: MAT_001, RO: 7800, E: 200e9, PR: 0.3}\nsections:\n  s: {ELFORM: 1, IHQ: 4}\n"
    "parts:\n  block: {material: m, section: s}\nmesh:\n  boxes:\n    - {part: block, size: [0.01, 0.01, 0.01], elements: [2, 2, 2]}\n"
    "node_sets:\n  base: {plane: {axis: z, value: 0}}\nboundary_conditions:\n  - {node_set: base, fix: [x, y, z]}\n"
    "initial_velocity:\n  - {part: block, velocity: [0, 0, -1]}\n";

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// Frames (*.vtu) in the folder must be exactly those its .pvd lists.
void expect_only_listed_frames(const fs::path& dir, const std::string& name) {
  const auto listed = test::pvd_frames(dir / (name + ".pvd"));
  std::set<std::string> frames;
  for (const auto& n : names_in(dir))
    if (n.ends_with(".vtu")) frames.insert(n);
  EXPECT_EQ(frames, std::set<std::string>(listed.begin(), listed.end())) << name;
}

pid_t dead_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) std::_Exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

TEST(OutputFolder, ThreeScenesInTurnWithTheSameFolder) {
  test::TestDir tmp;
  const fs::path out = tmp / "out";
  std::string two = kBlock, three = kBlock;
  two.replace(two.find("termination_time: 2.0e-4"), 24, "termination_time: 4.0e-5");  // fewer frames
  three.replace(three.find("E: 200e9"), 8, "E: 100e9");
  const fs::path x = test::write_file(tmp / "x.yaml", kBlock), y = test::write_file(tmp / "y.yaml", two);
  const fs::path z = test::write_file(tmp / "z.yaml", three);

  ASSERT_EQ(plyimpact({"run", x.string(), "-o", out.string()}).code, 0);
  test::write_file(out / "notes.txt", "mine");
  std::string stale = ".x_0003.vtu.tmp.";  // appended: g++ 12 warns falsely on "." + std::string (PR 105329)
  stale += std::to_string(dead_pid());
  test::write_file(out / stale, "half a frame");
  const auto before = names_in(out);

  const auto refused = plyimpact({"run", y.string(), "-o", out.string()});
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find(out.string()), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("scene 'x'"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--replace"), std::string::npos) << refused.err;
  auto after_refusal = names_in(out);
  after_refusal.insert(stale);  // the only change a refused run may make: a dead process's temporary goes
  EXPECT_EQ(after_refusal, before);
  EXPECT_FALSE(fs::exists(out / stale));

  ASSERT_EQ(plyimpact({"run", y.string(), "-o", out.string(), "--replace"}).code, 0);
  EXPECT_TRUE(fs::exists(out / "notes.txt")) << "a file plyimpact does not write was removed";
  EXPECT_FALSE(fs::exists(out / "x.pvd"));
  expect_only_listed_frames(out, "y");
  EXPECT_EQ(test::pvd_frames(out / "y.pvd").size(), 5u);  // t = 0 and 4 frames

  // Same scene name, other settings: refused too.
  fs::copy_file(z, tmp / "y.yaml", fs::copy_options::overwrite_existing);
  const auto same_name = plyimpact({"run", (tmp / "y.yaml").string(), "-o", out.string()});
  EXPECT_EQ(same_name.code, 1);
  EXPECT_NE(same_name.err.find("other settings"), std::string::npos) << same_name.err;

  ASSERT_EQ(plyimpact({"run", z.string(), "-o", out.string(), "--replace"}).code, 0);
  expect_only_listed_frames(out, "z");
  EXPECT_EQ(test::pvd_frames(out / "z.pvd").size(), 21u);
  for (const auto& n : names_in(out)) EXPECT_EQ(n.find(".tmp."), std::string::npos) << n;
}

TEST(OutputFolder, RerunOfTheSameSceneReplacesItsOwnResults) {
  test::TestDir tmp;
  const fs::path out = tmp / "out";
  const fs::path x = test::write_file(tmp / "x.yaml", kBlock);
  ASSERT_EQ(plyimpact({"run", x.string(), "-o", out.string()}).code, 0);
  ASSERT_EQ(test::pvd_frames(out / "x.pvd").size(), 21u);
  // Output intervals may change without making it another scene; the longer run's frames go.
  ASSERT_EQ(plyimpact({"run", x.string(), "-o", out.string(), "--set", "output.interval=1.0e-4"}).code, 0);
  EXPECT_EQ(test::pvd_frames(out / "x.pvd").size(), 3u);
  expect_only_listed_frames(out, "x");
}

TEST(OutputFolder, RunThatFailsLeavesNoTemporary) {
  test::TestDir tmp;
  const fs::path out = tmp / "out";
  const fs::path x = test::write_file(tmp / "x.yaml", kBlock);
  // The history file is a directory: its write fails, the run stops with an error (exit 2).
  fs::create_directories(out / "history.csv");
  const auto r = plyimpact({"run", x.string(), "-o", out.string()});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  for (const auto& n : names_in(out)) EXPECT_EQ(n.find(".tmp."), std::string::npos) << n;
}

TEST(OutputFolder, LiveProcessesKeepTheirTemporaries) {
  test::TestDir tmp;
  const fs::path mine = tmp / (".a.vtu.tmp." + std::to_string(::getppid()));  // our parent lives
  test::write_file(mine, "x");
  output::remove_stale_temporaries(tmp.path());
  EXPECT_TRUE(fs::exists(mine));
  EXPECT_EQ(output::temporary_owner(".a.vtu.tmp.123"), 123);
  EXPECT_EQ(output::temporary_owner("a.vtu.tmp.123"), -1);
  EXPECT_EQ(output::temporary_owner(".a.vtu.tmp.12x"), -1);
}

TEST(RestartRefusal, DumpOfAnotherSceneVersionOrNoDumpAtAll) {
  test::TestDir tmp;
  const fs::path x = test::write_file(tmp / "x.yaml", kBlock);
  const fs::path out = tmp / "out";
  ASSERT_EQ(plyimpact({"run", x.string(), "-o", out.string(), "--set", "control.max_cycles=5"}).code, 2);
  const fs::path dump = out / "restart.dump";
  ASSERT_TRUE(fs::exists(dump));
  const auto listing = names_in(out);

  // Another scene: a changed material constant, by file or by --set.
  std::string other = kBlock;
  other.replace(other.find("E: 200e9"), 8, "E: 100e9");
  const fs::path y = test::write_file(tmp / "x2.yaml", other);
  const auto foreign = plyimpact({"run", y.string(), "-o", (tmp / "o2").string(), "--restart", dump.string()});
  EXPECT_EQ(foreign.code, 1);
  EXPECT_NE(foreign.err.find(dump.string()), std::string::npos) << foreign.err;
  EXPECT_NE(foreign.err.find("another scene"), std::string::npos) << foreign.err;
  EXPECT_FALSE(fs::exists(tmp / "o2")) << "a refused restart wrote something";
  const auto by_set = plyimpact({"run", x.string(), "-o", out.string(), "--restart", dump.string(), "--set",
                                 "materials.m.PR=0.25"});
  EXPECT_EQ(by_set.code, 1);
  EXPECT_NE(by_set.err.find("another scene"), std::string::npos) << by_set.err;
  EXPECT_EQ(names_in(out), listing);

  // What may change: termination time, max_cycles, threads, output intervals.
  const auto allowed = plyimpact({"run", x.string(), "-o", out.string(), "--restart", dump.string(), "--set",
                                  "control.termination_time=3.0e-4", "output.history_interval=1.0e-6", "--threads",
                                  "2"});
  EXPECT_EQ(allowed.code, 0) << allowed.out << allowed.err;

  // Another program version: the version text in the dump's header changed.
  std::string bytes = test::read_file(dump);
  const std::string version = PLYIMPACT_VERSION;
  const std::size_t at = bytes.find(version);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, version.size(), std::string(version.size(), '9'));
  const fs::path old = test::write_file(tmp / "old.dump", "");
  std::ofstream(old, std::ios::binary) << bytes;
  const auto versioned = plyimpact({"run", x.string(), "-o", out.string(), "--restart", old.string()});
  EXPECT_EQ(versioned.code, 1);
  EXPECT_NE(versioned.err.find("written by plyimpact " + std::string(version.size(), '9')), std::string::npos)
      << versioned.err;

  // Not a dump, and a truncated one.
  const auto not_dump = plyimpact({"run", x.string(), "-o", out.string(), "--restart", x.string()});
  EXPECT_EQ(not_dump.code, 1);
  EXPECT_NE(not_dump.err.find("not a plyimpact run state"), std::string::npos) << not_dump.err;
  const std::string whole = test::read_file(dump);
  const fs::path cut = tmp / "cut.dump";
  std::ofstream(cut, std::ios::binary) << whole.substr(0, whole.size() / 2);
  const auto truncated = plyimpact({"run", x.string(), "-o", out.string(), "--restart", cut.string()});
  EXPECT_EQ(truncated.code, 1);
  EXPECT_NE(truncated.err.find("truncated"), std::string::npos) << truncated.err;
}

}  // namespace
}  // namespace plyimpact
