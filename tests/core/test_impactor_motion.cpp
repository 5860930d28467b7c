// A deformable impactor's motion columns (solver/impactor_motion.hpp) on free flight: a steel sphere
// meshed with hexahedra, launched at 20 m/s with nothing to hit for 50 us. No force acts, so the
// centre of mass moves at the launch velocity (x = x0 + v t) and the impactor's kinetic energy stays
// 1/2 m v^2. Tolerances: velocity and energy 1e-12 relative (central difference moves an unforced
// node exactly; the sums are round-off); position 1e-9 of the distance travelled (the sum of
// the steps equals the time to round-off).
#include <gtest/gtest.h>

#include <cmath>

#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

TEST(ImpactorMotion, FreeFlightKeepsTheLaunchVelocityAndEnergy) {
  const std::string yaml =
      "units: mm-t-s-MPa\n"
      "control: {termination_time: 5.0e-5}\n"
      "materials:\n"
      "  ply: {card: MAT_001, RO: 1600 kg/m^3, E: 50 GPa, PR: 0.3}\n"
      "  steel: {card: MAT_001, RO: 7850 kg/m^3, E: 210 GPa, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
      "laminate: {length: 20, width: 20, ply_thickness: 1, stacking: [0], material: ply, section: s, element_size: 5}\n"
      "impactor: {shape: sphere, diameter: 6, gap: 5, velocity: 20 m/s, rigid: false, material: steel, section: s,\n"
      "           element_size: 1.5}\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "flight.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  solver::Solver solver(model);
  const solver::ForceContributor* motion = nullptr;
  for (const auto& c : solver.contributors())
    if (c->name() == "impactor_motion") motion = c.get();
  ASSERT_NE(motion, nullptr);
  std::vector<double> start;
  motion->history_values(start);
  ASSERT_EQ(start.size(), 7u);
  EXPECT_NEAR(start[5], -20.0, 20e-12);
  const double kinetic0 = start[6];
  while (solver.state().time < 5.0e-5 * (1 - 1e-12)) solver.step();
  std::vector<double> end;
  motion->history_values(end);
  const double t = solver.state().time;
  EXPECT_NEAR(end[5], -20.0, 20e-12);
  EXPECT_NEAR(end[6], kinetic0, 1e-12 * kinetic0);
  EXPECT_NEAR(end[2] - start[2], -20.0 * t, 1e-9 * 20.0 * t);
  EXPECT_NEAR(end[0], start[0], 1e-15);
}

}  // namespace
}  // namespace plyimpact
