// Stability at high velocity: the seed's high-velocity set-up (configs/high_velocity_impact.yaml:
// BMS8-212 *MAT_054 plate, *MAT_003 steel sphere at 500 m/s, eroding contact) runs to its end time
// without a non-finite value, an inverted element or a collapsing step; plies erode through
// their strain criteria, the summary names parts and causes, and the energy balance holds: the
// erosion bookkeeping keeps eroded energy in the totals (tolerance 2 %: penalty contact and
// erosion release energy in steps; a runaway would exceed it by orders of magnitude). The plate's
// angle-change interfaces carry the seed's stiff Table 8.2 tiebreak (CN = 1.5e5 kN/mm^3, whose
// pairs set a step 17.6x below the elements'): the run must stay stable through perforation with
// them and never hold a negative interface energy. (Table 8.2's strengths, NFLS 1357 MPa and SFLS
// 10590 MPa, exceed what the plies carry: the plies erode at their strains to failure before any
// pair reaches onset, so nothing delaminates in this scene.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "run/run.hpp"

namespace plyimpact {
namespace {

TEST(HighVelocity, SteelSphereThroughCompositePlateIsStable) {
  const config::Scene scene = config::load_scene(PLYIMPACT_SOURCE_DIR "/configs/high_velocity_impact.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  const auto dir = std::filesystem::temp_directory_path() / ("plyimpact_high_velocity_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  run::RunOptions options;
  options.output_dir = dir;
  const run::RunReport r = run::run_model(model, options);
  ASSERT_TRUE(r.completed) << r.stop_reason;
  EXPECT_NEAR(r.energy_ratio, 1.0, 0.02);
  std::ifstream in(dir / "summary.json");
  std::stringstream json;
  json << in.rdbuf();
  EXPECT_NE(json.str().find("\"by_part_and_cause\""), std::string::npos);
  EXPECT_NE(json.str().find("\"cause\": \"DFAILT\""), std::string::npos) << json.str();
  const auto pos = json.str().find("\"eroded_elements\": ");
  ASSERT_NE(pos, std::string::npos);
  EXPECT_GT(std::stol(json.str().substr(pos + 19)), 0);  // the plate is perforated: plies erode
  for (const char* key : {"\"interface_elastic\": ", "\"interface_dissipated\": "}) {
    const auto at = json.str().find(key);
    ASSERT_NE(at, std::string::npos) << key;
    const double value = std::stod(json.str().substr(at + std::string(key).size()));
    EXPECT_GE(value, 0.0) << key;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace plyimpact
