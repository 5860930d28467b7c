// config/scene_loader: a complete scene round trip (every key, values in SI) and file handling.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "config/scene_loader.hpp"
#include "core/error.hpp"

namespace cfg = plyimpact::config;

namespace {

constexpr double kRel = 1e-12;
const std::string kScenes = std::string(PLYIMPACT_SOURCE_DIR) + "/tests/data/scenes/";

void expect_rel(double actual, double expected) {
  EXPECT_NEAR(actual, expected, kRel * std::abs(expected)) << "expected " << expected;
}

void expect_vec(const plyimpact::Vec3& a, const plyimpact::Vec3& b) {
  for (int i = 0; i < 3; ++i) expect_rel(a[i], b[i]);
}

}  // namespace

TEST(SceneLoader, GoodFullRoundTrip) {
  const cfg::Scene s = cfg::load_scene(kScenes + "good_full.yaml");
  EXPECT_EQ(s.name, "good_full");
  EXPECT_EQ(s.file, kScenes + "good_full.yaml");
  EXPECT_EQ(s.unit_system, "mm-t-s-MPa");

  expect_rel(s.control.termination_time, 2.0e-5);
  expect_rel(s.control.tssfac, 0.8);
  expect_rel(s.control.dt_min_ratio, 1.0e-4);
  expect_rel(s.control.hourglass_warn_ratio, 0.05);
  EXPECT_EQ(s.control.max_cycles, 100000);
  EXPECT_EQ(s.control.max_elements, 5000000);
  EXPECT_EQ(s.control.cycle_limit, 200000000);
  EXPECT_EQ(s.control.threads, 2);
  expect_rel(s.output.interval, 1e-6);
  expect_rel(s.output.history_interval, 1e-7);
  expect_rel(s.output.restart_interval, 2e-6);

  ASSERT_EQ(s.materials.size(), 2u);
  const cfg::MaterialSpec& steel = s.materials[0];
  EXPECT_EQ(steel.name, "steel");
  EXPECT_EQ(steel.card, "MAT_001");
  const auto& e = std::get<cfg::MatElastic>(steel.params);
  expect_rel(e.RO, 7850.0);
  expect_rel(e.E, 2.1e11);
  expect_rel(e.PR, 0.3);
  EXPECT_EQ(steel.where.key_path, "materials.steel");
  EXPECT_EQ(steel.where.line, 18);
  EXPECT_EQ(steel.where.column, 5);

  const cfg::MaterialSpec& ply = s.materials[1];
  EXPECT_EQ(ply.name, "ply");
  EXPECT_EQ(ply.card, "MAT_002");
  const auto& o = std::get<cfg::MatOrthotropicElastic>(ply.params);
  expect_rel(o.RO, 1550.0);
  expect_rel(o.EA, 1.57e11);
  expect_rel(o.EB, 8.5e9);
  expect_rel(o.EC, 8.5e9);
  expect_rel(o.PRBA, 0.019);
  expect_rel(o.PRCA, 0.019);
  expect_rel(o.PRCB, 0.53);
  expect_rel(o.GAB, 4.2e9);
  expect_rel(o.GBC, 2.2e9);
  expect_rel(o.GCA, 4.2e9);
  EXPECT_EQ(o.axes.AOPT, 2);
  expect_vec(o.axes.A, {1, 1, 0});
  expect_vec(o.axes.D, {0, 1, 0});
  expect_vec(o.axes.V, {0, 0, 1});
  expect_rel(o.axes.BETA, 0.5);
  EXPECT_EQ(ply.where.file, kScenes + "good_full.yaml");
  EXPECT_EQ(ply.where.line, 23);
  EXPECT_EQ(ply.where.column, 5);

  ASSERT_EQ(s.sections.size(), 2u);
  EXPECT_EQ(s.sections[0].name, "hex1");
  EXPECT_EQ(s.sections[0].ELFORM, 1);
  EXPECT_EQ(s.sections[0].IHQ, 4);
  expect_rel(s.sections[0].QM, 0.05);
  expect_rel(s.sections[0].Q1, 1.2);
  expect_rel(s.sections[0].Q2, 0.1);
  EXPECT_EQ(s.sections[1].name, "hex2");  // defaults
  EXPECT_EQ(s.sections[1].ELFORM, 1);
  EXPECT_EQ(s.sections[1].IHQ, 2);
  expect_rel(s.sections[1].QM, 0.1);
  expect_rel(s.sections[1].Q1, 1.5);
  expect_rel(s.sections[1].Q2, 0.06);
  EXPECT_EQ(s.sections[0].where.key_path, "sections.hex1");

  ASSERT_EQ(s.parts.size(), 2u);
  EXPECT_EQ(s.parts[0].name, "bar");
  EXPECT_EQ(s.parts[0].id, 1);
  EXPECT_EQ(s.parts[0].material, "steel");
  EXPECT_EQ(s.parts[0].section, "hex1");
  EXPECT_EQ(s.parts[0].beta, 0.0);
  EXPECT_EQ(s.parts[1].name, "laminate");
  EXPECT_EQ(s.parts[1].id, 7);
  EXPECT_EQ(s.parts[1].material, "ply");
  EXPECT_EQ(s.parts[1].section, "hex2");
  expect_rel(s.parts[1].beta, std::numbers::pi / 4);
  EXPECT_EQ(s.parts[1].where.key_path, "parts.laminate");

  ASSERT_EQ(s.boxes.size(), 2u);
  EXPECT_EQ(s.boxes[0].part, "bar");
  expect_vec(s.boxes[0].size, {0.1, 0.001, 0.002});
  EXPECT_EQ(s.boxes[0].elements, (std::array<int, 3>{100, 1, 2}));
  EXPECT_EQ(s.boxes[1].part, "laminate");
  expect_vec(s.boxes[1].origin, {0, 0, 0.01});
  expect_vec(s.boxes[1].size, {0.1, 0.01, 0.00025});
  EXPECT_EQ(s.boxes[1].elements, (std::array<int, 3>{50, 5, 1}));
  EXPECT_EQ(s.boxes[1].where.key_path, "mesh.boxes[1]");
  EXPECT_EQ(s.boxes[1].where.line, 57);
  EXPECT_EQ(s.boxes[1].where.column, 7);

  using K = cfg::NodeSetSpec::Kind;
  ASSERT_EQ(s.node_sets.size(), 5u);
  EXPECT_EQ(s.node_sets[0].name, "left");
  EXPECT_EQ(s.node_sets[0].kind, K::Plane);
  EXPECT_EQ(s.node_sets[0].plane_axis, 0);
  EXPECT_EQ(s.node_sets[0].plane_value, 0.0);
  expect_rel(s.node_sets[0].tolerance, 1e-6);
  EXPECT_EQ(s.node_sets[1].kind, K::Plane);
  EXPECT_EQ(s.node_sets[1].plane_axis, 2);
  expect_rel(s.node_sets[1].plane_value, 0.01025);
  EXPECT_EQ(s.node_sets[1].tolerance, 0.0);
  EXPECT_EQ(s.node_sets[2].kind, K::Box);
  expect_vec(s.node_sets[2].box_min, {0, 0, 0});
  expect_vec(s.node_sets[2].box_max, {0.001, 0.001, 0.001});
  EXPECT_EQ(s.node_sets[3].kind, K::Part);
  EXPECT_EQ(s.node_sets[3].part, "bar");
  EXPECT_EQ(s.node_sets[4].kind, K::All);
  EXPECT_EQ(s.node_sets[4].where.key_path, "node_sets.every");

  using B = cfg::BoundaryConditionSpec::Kind;
  ASSERT_EQ(s.boundary_conditions.size(), 3u);
  const auto& fix = s.boundary_conditions[0];
  EXPECT_EQ(fix.kind, B::Fixed);
  EXPECT_EQ(fix.node_set, "left");
  EXPECT_EQ(fix.dofs, (std::array<bool, 3>{true, false, true}));
  const auto& vconst = s.boundary_conditions[1];
  EXPECT_EQ(vconst.kind, B::Velocity);
  EXPECT_EQ(vconst.dofs, (std::array<bool, 3>{false, false, true}));
  ASSERT_EQ(vconst.curve.t.size(), 1u);
  EXPECT_EQ(vconst.curve.t[0], 0.0);
  expect_rel(vconst.curve.y[0], -5.0);
  const auto& vcurve = s.boundary_conditions[2];
  EXPECT_EQ(vcurve.node_set, "corner");
  EXPECT_EQ(vcurve.dofs, (std::array<bool, 3>{true, true, false}));
  ASSERT_EQ(vcurve.curve.t.size(), 3u);
  expect_rel(vcurve.curve.t[1], 1e-6);
  expect_rel(vcurve.curve.t[2], 1e-3);
  EXPECT_EQ(vcurve.curve.y[0], 0.0);
  expect_rel(vcurve.curve.y[1], 10.0);
  expect_rel(vcurve.curve.y[2], 10.0);
  EXPECT_EQ(vcurve.where.key_path, "boundary_conditions[2]");

  ASSERT_EQ(s.initial_velocities.size(), 2u);
  EXPECT_EQ(s.initial_velocities[0].part, "laminate");
  EXPECT_TRUE(s.initial_velocities[0].node_set.empty());
  expect_vec(s.initial_velocities[0].velocity, {0, 0, -5});
  EXPECT_EQ(s.initial_velocities[1].node_set, "barset");
  EXPECT_TRUE(s.initial_velocities[1].part.empty());
  expect_vec(s.initial_velocities[1].velocity, {1, 0, 0});
}

TEST(SceneLoader, MinimalSceneGetsDefaults) {
  const cfg::Scene s = cfg::load_scene_from_string(R"(units: SI
control: {termination_time: 1 ms}
materials: {steel: {card: ELASTIC, RO: 7850, E: 210e9, PR: 0.3}}
sections: {hex: {}}
parts: {a: {material: steel, section: hex}, b: {material: steel, section: hex}}
mesh: {boxes: [{part: a, size: [1, 1, 1], elements: [1, 1, 1]}]}
)",
                                                   "configs/minimal.yaml");
  EXPECT_EQ(s.name, "minimal");
  EXPECT_EQ(s.file, "configs/minimal.yaml");
  EXPECT_EQ(s.unit_system, "SI");
  expect_rel(s.control.termination_time, 1e-3);
  EXPECT_EQ(s.control.tssfac, 0.9);
  EXPECT_EQ(s.materials[0].card, "MAT_001");
  EXPECT_EQ(s.parts[0].id, 1);
  EXPECT_EQ(s.parts[1].id, 2);
  expect_vec(s.boxes[0].origin, {0, 0, 0});
  EXPECT_TRUE(s.node_sets.empty());
  EXPECT_TRUE(s.boundary_conditions.empty());
  EXPECT_TRUE(s.initial_velocities.empty());
  EXPECT_EQ(std::get<cfg::MatElastic>(s.materials[0].params).E, 210e9);
}

TEST(SceneLoader, MissingFileIsInputError) {
  try {
    cfg::load_scene(kScenes + "does_not_exist.yaml");
    FAIL() << "no InputError";
  } catch (const plyimpact::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does_not_exist.yaml: cannot open the scene file"), std::string::npos)
        << e.what();
  }
}

TEST(SceneLoader, DirectoryIsInputError) {
  EXPECT_THROW(cfg::load_scene(kScenes), plyimpact::InputError);
}
