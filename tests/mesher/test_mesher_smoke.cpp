// End to end: a small laminate with a rigid spherical impactor goes from YAML through gmsh into
// the model and runs a few cycles of the elastic solver; the impactor's surface is closed and its
// mass properties are the sphere's.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include <omp.h>

#include "scene_cards.hpp"
#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

using namespace plyimpact;

TEST(MesherSmoke, LaminateWithRigidSphereRunsAFewCycles) {
  const config::Scene scene = config::load_scene_from_string(R"(units: mm-t-s-MPa
control: {termination_time: 1.0e-5}
)" + std::string(test::kPlyCards) + R"(laminate:
  length: 30
  width: 20
  ply_thickness: 0.25
  stacking: "[0/45/-45/90]s"
  material: ply
  section: s
  element_size: 2
  refined_zone: {size: [6, 6], element_size: 1}
  interfaces: angle-change
  supports:
    clamp: {clamped: [x0, x1, y0, y1]}
impactor: {shape: sphere, diameter: 10, mass: 0.1 kg, gap: 0.5, velocity: 2 m/s, element_size: 2}
initial_velocity:
  - {part: ply_8_0, velocity: [0, 0, "-1 m/s"]}
)", "smoke.yaml");
  const mesh::Mesh m = mesh::mesh_scene(scene);
  const model::Model model = model::build_model(scene, m);
  EXPECT_EQ(model.interfaces.size(), 6u);  // 0/45/-45/90/90/-45/45/0: all but the 90/90 interface
  ASSERT_TRUE(model.impactor.has_value());
  const auto& imp = *model.impactor;
  EXPECT_TRUE(imp.rigid);
  EXPECT_DOUBLE_EQ(imp.mass, 0.1);
  EXPECT_NEAR(imp.inertia[0], 0.4 * 0.1 * 0.005 * 0.005, 1e-15);
  EXPECT_NEAR(imp.centre_of_mass[2], 2e-3 + 0.5e-3 + 5e-3, 1e-15);
  EXPECT_EQ(imp.velocity[2], -2.0);
  // Cubed sphere, 4 elements per patch edge (quarter circumference 7.85 mm at 2 mm): 6 x 16 quads,
  // 6 x 16 + 2 nodes; every node on the sphere; closed: every edge shared by exactly two quads.
  EXPECT_EQ(imp.surface_quads.size() / 4, 96u);
  EXPECT_EQ(imp.surface_coords.size() / 3, 98u);
  for (std::size_t a = 0; a < imp.surface_coords.size() / 3; ++a) {
    const double* p = &imp.surface_coords[3 * a];
    EXPECT_NEAR(std::hypot(p[0] - 0.015, p[1] - 0.010, p[2] - imp.centre_of_mass[2]), 0.005, 1e-9);
  }
  std::map<std::pair<int, int>, int> edges;
  double signed_volume = 0;  // divergence theorem: positive for outward quads
  for (std::size_t q = 0; q < imp.surface_quads.size() / 4; ++q) {
    const auto* c = &imp.surface_quads[4 * q];
    for (int k = 0; k < 4; ++k) edges[{std::min(c[k], c[(k + 1) % 4]), std::max(c[k], c[(k + 1) % 4])}]++;
    for (int t = 1; t < 3; ++t) {  // two triangles (0, t, t+1)
      const double* a = &imp.surface_coords[3 * std::size_t(c[0])];
      const double* b = &imp.surface_coords[3 * std::size_t(c[t])];
      const double* d = &imp.surface_coords[3 * std::size_t(c[t + 1])];
      signed_volume += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                        a[2] * (b[0] * d[1] - b[1] * d[0])) / 6;
    }
  }
  for (const auto& [e, n] : edges) EXPECT_EQ(n, 2);
  const double sphere = std::numbers::pi * 1e-6 / 6;  // d = 10 mm
  EXPECT_GT(signed_volume, 0.9 * sphere);
  EXPECT_LT(signed_volume, sphere);

  solver::Solver solver(model);
  for (int i = 0; i < 5; ++i) solver.step();
  const auto& st = solver.state();
  EXPECT_GT(st.time, 0.0);
  EXPECT_EQ(st.cycle, 5);
}

// A deformable impactor runs as an ordinary MAT_001 part: in free flight (0.5 mm gap, no contact
// in 5 cycles) a uniform translation strains nothing, so every impactor node keeps the initial
// velocity (to round-off) while the plate is loaded by its own initial velocity.
TEST(MesherSmoke, DeformableImpactorFliesAsAnOrdinaryPart) {
  const config::Scene scene = config::load_scene_from_string(R"(units: mm-t-s-MPa
control: {termination_time: 1.0e-5}
)" + std::string(test::kPlyAndSteelCards) + R"(laminate: {length: 30, width: 20, ply_thickness: 0.25, stacking: "[0/90]s", material: ply, section: s,
           element_size: 2, interfaces: angle-change, supports: {clamp: {clamped: [x0, x1]}}}
impactor: {shape: hemispherical_cylinder, diameter: 8, length: 16, mass: 0.05 kg, gap: 0.5, velocity: 2 m/s,
           rigid: false, material: steel, section: s, element_size: 2}
initial_velocity:
  - {part: ply_4_0, velocity: [0, 0, "-1 m/s"]}
)", "smoke_deformable.yaml");
  const mesh::Mesh m = mesh::mesh_scene(scene);
  const model::Model model = model::build_model(scene, m);
  const int part = scene.impactor->part;
  std::vector<bool> on_impactor(m.num_nodes(), false);
  for (std::size_t e = 0; e < m.num_elements(); ++e)
    if (m.element_part[e] == part)
      for (int k = 0; k < 8; ++k) on_impactor[std::size_t(m.hex[8 * e + k])] = true;
  solver::Solver solver(model);
  for (int i = 0; i < 5; ++i) solver.step();
  const auto& v = solver.state().v;
  std::size_t checked = 0;
  for (std::size_t n = 0; n < m.num_nodes(); ++n) {
    if (!on_impactor[n]) continue;
    ++checked;
    EXPECT_NEAR(v[3 * n], 0.0, 1e-9);
    EXPECT_NEAR(v[3 * n + 1], 0.0, 1e-9);
    EXPECT_NEAR(v[3 * n + 2], -2.0, 1e-9);
  }
  EXPECT_GT(checked, 100u);
}

// gmsh::initialize sets OpenMP's thread count to its General.NumThreads (1); the session must put
// back what the process had, or the solver of every laminate scene runs on one thread. gmsh is
// initialised once per process (first mesh), and each test runs in its own process (ctest).
TEST(MesherSmoke, MeshingKeepsTheOpenMpThreadCount) {
  omp_set_num_threads(3);  // not 1 (gmsh's default) and not the test environment's 1
  const config::Scene scene = config::load_scene_from_string(R"(units: mm-t-s-MPa
control: {termination_time: 1.0e-5}
)" + std::string(test::kPlyCards) + R"(laminate: {length: 10, width: 10, ply_thickness: 0.25, stacking: "[0/90]", material: ply, section: s,
           element_size: 5, supports: {clamp: {clamped: [x0]}}}
)", "smoke_threads.yaml");
  const mesh::Mesh m = mesh::mesh_scene(scene);
  EXPECT_EQ(m.num_elements(), 8u);
  EXPECT_EQ(omp_get_max_threads(), 3);
}
