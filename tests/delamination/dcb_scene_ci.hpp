// The shipped DCB scene (configs/dcb_t800s_m21.yaml) at the size CI affords, run through the whole
// chain (scene loader with overrides, mesher, model, solver, run observers writing history.csv),
// for test_dcb_scene and test_cohesive_zone_length. CI size: a 2 mm wide strip (beam theory carries
// the width as a factor), 60 mm long with a0 = 25 mm, the ends opened at 1.1 m/s each after a
// 0.5 ms ramp (the arms' first bending period at a0 is ~0.25 ms), run to 3 ms: the crack grows
// from 25 to ~43 mm. The segments stay 1 mm, as in the shipped scene.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "config/overrides.hpp"
#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "run/run.hpp"

namespace plyimpact::dcb_ci {

constexpr double kE11 = 157e9, kE22 = 8.5e9, kG13 = 4.2e9;  // Pa, the scene's T800S/M21 card
constexpr double kArm = 1.5e-3, kWidth = 2e-3, kA0 = 25e-3;  // m: arm thickness, CI width, pre-crack
constexpr double kSegment = 1e-3;                            // m, the scene's element_size
constexpr double kGIc = 765, kGIIc = 1250;                   // J/m^2, ERATEN and ERATES of the scene

// `extra`: further --set arguments (e.g. "laminate.interfaces.process_zone_elements=3").
inline std::vector<config::SceneOverride> ci_overrides(double nfls_mpa, double sfls_mpa,
                                                       const std::vector<std::string>& extra = {}) {
  std::vector<config::SceneOverride> o;
  for (const char* s : {"laminate.width=2", "laminate.length=60", "node_sets.block_top.box.max=[0.01, 3, 3.1]",
                        "node_sets.block_bottom.box.max=[0.01, 3, 1.49]", "laminate.interfaces.precrack.x=[0, 25]",
                        "control.termination_time=3e-3", "output.interval=10e-3", "output.history_interval=5e-6",
                        "boundary_conditions[0].velocity.ramp=0.5 ms", "boundary_conditions[1].velocity.ramp=0.5 ms",
                        "boundary_conditions[0].velocity.value=1.1 m/s",
                        "boundary_conditions[1].velocity.value=-1.1 m/s"})
    o.push_back(config::parse_set_argument(s));
  o.push_back(config::parse_set_argument("laminate.interfaces.NFLS=" + std::to_string(nfls_mpa) + " MPa"));
  o.push_back(config::parse_set_argument("laminate.interfaces.SFLS=" + std::to_string(sfls_mpa) + " MPa"));
  for (const auto& e : extra) o.push_back(config::parse_set_argument(e));
  return o;
}

struct CiRun {
  std::filesystem::path history;
  double wall = 0;  // s
  bool completed = false;
};

// Runs the scene at CI size into PLYIMPACT_BINARY_DIR/<dir>; returns its history.csv.
inline CiRun run_dcb_ci(const std::string& dir, double nfls_mpa, double sfls_mpa,
                        const std::vector<std::string>& extra = {}) {
  const auto start = std::chrono::steady_clock::now();
  const std::string path = std::string(PLYIMPACT_SOURCE_DIR) + "/configs/dcb_t800s_m21.yaml";
  const config::Scene scene = config::load_scene(path, ci_overrides(nfls_mpa, sfls_mpa, extra));
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  run::RunOptions options;
  options.output_dir = std::filesystem::path(PLYIMPACT_BINARY_DIR) / "test_output" / dir;
  const run::RunReport report = run::run_model(model, options);
  CiRun r;
  r.history = report.history;
  r.completed = report.completed;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// Corrected beam theory (Williams 1989, the end correction of test_dcb.cpp): crack-length
// correction Delta = chi h and the load at which a crack of length a propagates.
inline double williams_delta() {
  const double gamma = 1.18 * std::sqrt(kE11 * kE22) / kG13;
  const double r = gamma / (1 + gamma);
  return kArm * std::sqrt(kE11 / (11 * kG13) * (3 - 2 * r * r));
}
inline double critical_load(double a) {
  return kWidth / (a + williams_delta()) * std::sqrt(kE11 * kArm * kArm * kArm * kGIc / 12);
}

}  // namespace plyimpact::dcb_ci
