// Command line: a refused scene writes nothing and names file:line:column; check prints the model
// summary (subsystems on/off, stable step and its controlling element); run writes the result set.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/application.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

// A directory of its own per test and process: ctest runs the tests of this file side by side
// (-j), and they write scenes and results under the same names.
fs::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() /
                       ("plyimpact_cli_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

fs::path write_scene(const std::string& name, const std::string& text) {
  const fs::path p = test_dir() / name;
  std::ofstream(p) << text;
  return p;
}

const char* kGood =
    "units: SI\ncontrol: {termination_time: 2.0e-6}\noutput: {interval: 1.0e-6}\nmaterials:\n"
    "  m: {card: MAT_001, RO: 7800, E: 200e9, PR: 0.3}\nsections:\n  s: {ELFORM: 1, IHQ: 4}\n"
    "parts:\n  block: {material: m, section: s}\nmesh:\n  boxes:\n    - {part: block, size: [0.01, 0.01, 0.01], elements: [4, 4, 4]}\n"
    "node_sets:\n  base: {plane: {axis: z, value: 0}}\nboundary_conditions:\n  - {node_set: base, fix: [x, y, z]}\n"
    "initial_velocity:\n  - {part: block, velocity: [0, 0, -1]}\n";

int run(const std::vector<std::string>& args, std::string& out, std::string& err) {
  std::ostringstream o, e;
  const int code = app::run_application(args, o, e);
  out = o.str();
  err = e.str();
  return code;
}

TEST(Cli, RefusedSceneWritesNothing) {
  const fs::path scene = write_scene("plyimpact_cli_bad.yaml",
                                     std::string(kGood).replace(std::string(kGood).find("RO: 7800"), 8, "RO: -7800"));
  const fs::path out_dir = test_dir() / "out";
  fs::remove_all(out_dir);
  std::string out, err;
  EXPECT_EQ(1, run({"run", scene.string(), "-o", out_dir.string()}, out, err));
  EXPECT_NE(err.find("plyimpact_cli_bad.yaml:5:"), std::string::npos) << err;
  EXPECT_NE(err.find("materials.m.RO"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out_dir)) << "a refused scene must not create its output directory";
  fs::remove_all(test_dir());
}

TEST(Cli, CheckReportsModelSubsystemsAndStep) {
  const fs::path scene = write_scene("plyimpact_cli_good.yaml", kGood);
  std::string out, err;
  ASSERT_EQ(0, run({"check", scene.string()}, out, err)) << err;
  EXPECT_NE(out.find("nodes: 125, elements: 64"), std::string::npos) << out;
  EXPECT_NE(out.find("[off] contact: left out"), std::string::npos) << out;
  EXPECT_NE(out.find("[on ] hourglass_control: IHQ 4"), std::string::npos) << out;
  EXPECT_NE(out.find("stable time step"), std::string::npos) << out;
  EXPECT_NE(out.find("controlling element"), std::string::npos) << out;
  EXPECT_NE(out.find("memory estimate"), std::string::npos) << out;
  fs::remove_all(test_dir());
}

TEST(Cli, RunWritesSeriesHistoryAndSummary) {
  const fs::path scene = write_scene("plyimpact_cli_good.yaml", kGood);
  const fs::path out_dir = test_dir() / "out";
  fs::remove_all(out_dir);
  std::string out, err;
  ASSERT_EQ(0, run({"run", scene.string(), "-o", out_dir.string()}, out, err)) << err << out;
  EXPECT_TRUE(fs::exists(out_dir / "plyimpact_cli_good.pvd"));
  EXPECT_TRUE(fs::exists(out_dir / "plyimpact_cli_good_0000.vtu"));
  EXPECT_TRUE(fs::exists(out_dir / "history.csv"));
  std::ifstream in(out_dir / "summary.json");
  std::stringstream json;
  json << in.rdbuf();
  EXPECT_NE(json.str().find("\"status\": \"completed\""), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"ns_per_element_cycle\""), std::string::npos);
  fs::remove_all(test_dir());
}

TEST(Cli, UsageHelpAndVersion) {
  std::string out, err;
  EXPECT_EQ(64, run({}, out, err));
  EXPECT_EQ(0, run({"--help"}, out, err));
  EXPECT_NE(out.find("run SCENE.yaml [-o DIR]"), std::string::npos);
  EXPECT_EQ(0, run({"--version"}, out, err));
  EXPECT_NE(out.find("plyimpact 0."), std::string::npos);
  EXPECT_EQ(64, run({"run", "a.yaml", "--bogus"}, out, err));
}

}  // namespace
}  // namespace plyimpact
