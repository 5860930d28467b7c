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
  EXPECT_NE(out.find("[on ] hourglass_control: IHQ 4 (64 one-point elements)"), std::string::npos) << out;
  EXPECT_NE(out.find("[off] fully_integrated_elements: no ELFORM 2 part"), std::string::npos) << out;
  EXPECT_NE(out.find("stable time step"), std::string::npos) << out;
  EXPECT_NE(out.find("controlling element"), std::string::npos) << out;
  EXPECT_NE(out.find("memory estimate"), std::string::npos) << out;
  fs::remove_all(test_dir());
}

// check's memory estimate counts the run state, whose largest part on a *MAT_054 model is the
// material history of every integration point: 29 values per point, so a fully integrated block
// of 1,600 elements holds 1600 x 8 x 29 x 8 B = 2.97 MB of it against 0.37 MB with one point. The
// estimate must cover at least history and stresses (3.58 MB; 0.45 MB with one point).
double estimate_mib(const std::string& elform) {
  const std::string scene =
      "units: SI\ncontrol: {termination_time: 1.0e-6}\nmaterials:\n"
      "  ply: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], XT: 2.0e9, XC: 1.2e9,"
      " YT: 50e6, YC: 200e6, SC: 70e6}\n"
      "sections:\n  s: " + elform + "\nparts:\n  plate: {material: ply, section: s}\n"
      "mesh:\n  boxes:\n    - {part: plate, size: [0.04, 0.04, 0.001], elements: [20, 20, 4]}\n";
  const fs::path path = write_scene("plyimpact_cli_memory.yaml", scene);
  std::string out, err;
  EXPECT_EQ(0, run({"check", path.string()}, out, err)) << err;
  const auto at = out.find("memory estimate: ");
  EXPECT_NE(at, std::string::npos) << out;
  return at == std::string::npos ? 0.0 : std::stod(out.substr(at + 17));
}

TEST(Cli, MemoryEstimateCountsEveryIntegrationPointsHistory) {
  const double mib = 1048576.0;
  const double full = estimate_mib("{ELFORM: -2}"), one = estimate_mib("{ELFORM: 1, IHQ: 6, QM: 1}");
  EXPECT_GE(full, 1600.0 * 8 * (29 + 6) * 8 / mib);
  EXPECT_GE(one, 1600.0 * (29 + 6) * 8 / mib);
  // Seven more points per element, less the one-point element's 12 hourglass forces and 6 IHQ 6
  // moduli per element, less the printed rounding (0.05 MiB each).
  EXPECT_GE(full - one, 1600.0 * (7 * (29 + 6) - 18) * 8 / mib - 0.1) << "the seven more points per element";
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
