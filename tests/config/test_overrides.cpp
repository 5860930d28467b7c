// Command-line overrides (`--set key.path=value`, `--threads N`): they change the scene as if the
// file said so (same units, same validation), and every refusal names the override, never a line
// of the file the value did not come from.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/application.hpp"
#include "config/overrides.hpp"
#include "config/scene_loader.hpp"
#include "core/error.hpp"

namespace plyimpact {
namespace {

namespace cfg = config;

// mm-t-s-MPa so that a plain number in an override is visibly taken in the scene's units.
const char* kScene = R"(units: mm-t-s-MPa
control: {termination_time: 2.0e-6, tssfac: 0.9}
materials:
  m: {card: MAT_001, RO: 7.8e-9, E: 200000, PR: 0.3}
sections:
  s: {ELFORM: 1, IHQ: 4}
parts:
  a: {material: m, section: s}
  b: {material: m, section: s}
mesh:
  boxes:
    - {part: a, size: [10, 10, 10], elements: [2, 2, 2]}
    - {part: b, origin: [0, 0, 10], size: [10, 10, 10], elements: [2, 2, 2]}
initial_velocity:
  - {part: b, velocity: [0, 0, -1000]}
contacts:
  - {name: ab, type: automatic_surface_to_surface, surfaces: [a, b]}
  - {name: self, type: automatic_single_surface, parts: [a, b]}
)";

cfg::Scene load(std::vector<std::string> sets) {
  std::vector<cfg::SceneOverride> ov;
  for (const auto& s : sets) ov.push_back(cfg::parse_set_argument(s));
  return cfg::load_scene_from_string(kScene, "scene.yaml", ov);
}

std::string error_of(std::vector<std::string> sets) {
  try {
    load(std::move(sets));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

const cfg::MatElastic& material(const cfg::Scene& s) { return std::get<cfg::MatElastic>(s.materials.at(0).params); }

TEST(Overrides, ChangeTheLoadedSceneWithTheScenesUnits) {
  const cfg::Scene base = load({});
  EXPECT_DOUBLE_EQ(base.control.tssfac, 0.9);
  EXPECT_DOUBLE_EQ(material(base).E, 200000 * 1e6);
  const cfg::Scene s = load({"control.tssfac=0.5", "materials.m.E=100000", "parts.b.material=m",
                             "initial_velocity[0].velocity=[0, 0, -5 m/s]"});
  EXPECT_DOUBLE_EQ(s.control.tssfac, 0.5);
  EXPECT_DOUBLE_EQ(material(s).E, 100000 * 1e6) << "plain number in the scene's unit system (MPa)";
  EXPECT_DOUBLE_EQ(s.initial_velocities.at(0).velocity[2], -5.0);
  const cfg::Scene g = load({"materials.m.E=70 GPa"});
  EXPECT_DOUBLE_EQ(material(g).E, 70e9);
}

TEST(Overrides, ListItemsByIndexOrNameAndNewOptionalKeys) {
  const cfg::Scene s = load({"contacts[0].SOFT=2", "contacts[self].SOFSCL=0.2", "contacts.1.SFS=3",
                             "output.interval=1e-6", "control.max_cycles=7"});
  EXPECT_EQ(s.contacts.at(0).SOFT, 2);
  EXPECT_EQ(s.contacts.at(1).SOFT, 0);
  EXPECT_DOUBLE_EQ(s.contacts.at(1).SOFSCL, 0.2);
  EXPECT_DOUBLE_EQ(s.contacts.at(1).SFS, 3.0);
  EXPECT_DOUBLE_EQ(s.output.interval, 1e-6) << "the scene has no output: section; the override adds it";
  EXPECT_EQ(s.control.max_cycles, 7);
  // A whole section as a YAML value; a later override wins over an earlier one.
  const cfg::Scene t = load({"control={termination_time: 1e-6}", "control.tssfac=0.3"});
  EXPECT_DOUBLE_EQ(t.control.termination_time, 1e-6);
  EXPECT_DOUBLE_EQ(t.control.tssfac, 0.3);
}

TEST(Overrides, UnknownKeyIsRefusedNamingTheOverride) {
  const std::string e = error_of({"control.tsfac=0.8"});
  EXPECT_EQ(e.rfind("--set control.tsfac=0.8: control.tsfac: unknown key 'tsfac' (did you mean 'tssfac'?)", 0), 0u)
      << e;
  EXPECT_NE(e.find("allowed keys termination_time, tssfac"), std::string::npos) << e;
  const std::string e2 = error_of({"solver.dt=1"});
  EXPECT_EQ(e2.rfind("--set solver.dt=1: solver: unknown key 'solver'", 0), 0u) << e2;
  const std::string e3 = error_of({"materials.m.EA=1"});
  EXPECT_EQ(e3.rfind("--set materials.m.EA=1: materials.m.EA: unknown key 'EA'", 0), 0u) << e3;
}

TEST(Overrides, BadValueIsRefusedNamingTheOverrideNotTheFile) {
  const std::string e = error_of({"control.tssfac=1.5"});
  EXPECT_EQ(e.rfind("--set control.tssfac=1.5: control.tssfac: tssfac must be in (0, 1]", 0), 0u) << e;
  const std::string e2 = error_of({"materials.m.E=100 kg"});
  EXPECT_EQ(e2.rfind("--set materials.m.E=100 kg: materials.m.E:", 0), 0u) << e2;
  EXPECT_EQ(e2.find("scene.yaml"), std::string::npos) << e2;
  const std::string e3 = error_of({"contacts[0].SOFT=3"});
  EXPECT_EQ(e3.rfind("--set contacts[0].SOFT=3: contacts[0].SOFT: SOFT must be one of 0, 1, 2", 0), 0u) << e3;
  const std::string e4 = error_of({"control.tssfac=[1, 2"});
  EXPECT_EQ(e4.rfind("--set control.tssfac=[1, 2: the value is not valid YAML", 0), 0u) << e4;
  // Values from the file are still located in the file.
  const std::string e5 = error_of({"control.tssfac=0.5", "materials.m.PR=0.7"});
  EXPECT_EQ(e5.rfind("--set materials.m.PR=0.7:", 0), 0u) << e5;
}

TEST(Overrides, PathsThatDoNotFitTheTreeAreRefused) {
  EXPECT_EQ(error_of({"contacts[2].SOFT=1"}).rfind("--set contacts[2].SOFT=1: contacts: index 2 is past the end", 0), 0u);
  EXPECT_NE(error_of({"contacts[xy].SOFT=1"}).find("no item named 'xy'; allowed an index 0..1 or a name: ab, self"),
            std::string::npos);
  EXPECT_NE(error_of({"control.tssfac.x=1"}).find("control.tssfac is a single value, not a section"), std::string::npos);
  EXPECT_NE(error_of({"contacts.SOFT=1"}).find("contacts is a list"), std::string::npos);
  EXPECT_THROW(cfg::parse_set_argument("control.tssfac"), InputError);
  EXPECT_THROW(cfg::parse_set_argument("=3"), InputError);
  EXPECT_THROW(cfg::parse_set_argument("a..b=3"), InputError);
  EXPECT_THROW(cfg::parse_set_argument("a[=3"), InputError);
}

TEST(Overrides, ThreadsSetsTheThreadCount) {
  EXPECT_EQ(load({}).control.threads, 0);
  const cfg::Scene s = cfg::load_scene_from_string(kScene, "scene.yaml", {cfg::threads_override("3")});
  EXPECT_EQ(s.control.threads, 3);
  try {
    cfg::load_scene_from_string(kScene, "scene.yaml", {cfg::threads_override("two")});
    FAIL() << "--threads two accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--threads two: control.threads: expected an integer", 0), 0u) << e.what();
  }
}

TEST(Overrides, CommandLine) {
  const std::filesystem::path scene = std::filesystem::temp_directory_path() / ("plyimpact_overrides_cli_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(scene) << kScene;
  std::ostringstream out, err;
  EXPECT_EQ(app::run_application({"check", scene.string(), "--set", "control.tsfac=0.8"}, out, err), 1);
  EXPECT_EQ(err.str().rfind("error: --set control.tsfac=0.8: control.tsfac: unknown key 'tsfac'", 0), 0u) << err.str();
  std::ostringstream out2, err2;
  EXPECT_EQ(app::run_application({"check", scene.string(), "--threads", "2", "--set", "control.tssfac=0.45",
                                  "contacts[ab].SOFT=1"},
                                 out2, err2),
            0)
      << err2.str();
  EXPECT_NE(out2.str().find("overrides: --threads 2; --set control.tssfac=0.45; --set contacts[ab].SOFT=1;"),
            std::string::npos)
      << out2.str();
  EXPECT_NE(out2.str().find("TSSFAC 0.45 applied"), std::string::npos) << out2.str();
  EXPECT_NE(out2.str().find("contact ab: SOFT 1"), std::string::npos) << out2.str();
  std::filesystem::remove(scene);
}

}  // namespace
}  // namespace plyimpact
