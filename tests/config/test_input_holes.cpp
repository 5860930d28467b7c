// Input holes: values that used to pass the scene loader and then wrapped, hung, ran out of memory
// or fed nan to the solver. Each test writes the hole into a small valid scene and checks that it is
// now refused at file:line:col with the key and what is allowed (or, for the estimates, that the
// estimate agrees with what the mesher and the solver then make).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/application.hpp"
#include "config/plausible_range.hpp"
#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "mesh/scene_mesher.hpp"
#include "mesh/size_estimate.hpp"
#include "model/model.hpp"
#include "run/cycle_budget.hpp"
#include "run/progress_line.hpp"
#include "solver/solver.hpp"

namespace cfg = plyimpact::config;
namespace mesh = plyimpact::mesh;
namespace run = plyimpact::run;

namespace {

// clang-format off
const std::string kBoxes =
    "units: SI\n"                                   //  1
    "control:\n"                                    //  2
    "  termination_time: 1.0e-5\n"                  //  3
    "materials:\n"                                  //  4
    "  steel:\n"                                    //  5
    "    card: MAT_001\n"                           //  6
    "    RO: 7850\n"                                //  7
    "    E: 210 GPa\n"                              //  8
    "    PR: 0.3\n"                                 //  9
    "sections:\n"                                   // 10
    "  hex1: {ELFORM: 1, IHQ: 4}\n"                 // 11
    "parts:\n"                                      // 12
    "  bar: {material: steel, section: hex1}\n"     // 13
    "mesh:\n"                                       // 14
    "  boxes:\n"                                    // 15
    "    - part: bar\n"                             // 16
    "      size: [0.1, 0.01, 0.01]\n"               // 17
    "      elements: [10, 1, 1]\n"                  // 18
    "initial_velocity:\n"                           // 19
    "  - {part: bar, velocity: [0, 0, -5]}\n";      // 20

const std::string kLaminate =
    "units: mm-t-s-MPa\n"                                              //  1
    "control:\n"                                                       //  2
    "  termination_time: 1.0e-5\n"                                     //  3
    "materials:\n"                                                     //  4
    "  ply:\n"                                                         //  5
    "    card: MAT_002\n"                                              //  6
    "    RO: 1.55e-9\n"                                                //  7
    "    EA: 157 GPa\n"                                                //  8
    "    EB: 8.5 GPa\n"                                                //  9
    "    EC: 8.5 GPa\n"                                                // 10
    "    PRBA: 0.019\n"                                                // 11
    "    PRCA: 0.019\n"                                                // 12
    "    PRCB: 0.53\n"                                                 // 13
    "    GAB: 4.2 GPa\n"                                               // 14
    "    GBC: 2.2 GPa\n"                                               // 15
    "    GCA: 4.2 GPa\n"                                               // 16
    "    AOPT: 2\n"                                                    // 17
    "    A: [1, 0, 0]\n"                                               // 18
    "    D: [0, 1, 0]\n"                                               // 19
    "  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}\n"     // 20
    "sections:\n"                                                      // 21
    "  s: {}\n"                                                        // 22
    "laminate:\n"                                                      // 23
    "  length: 40\n"                                                   // 24
    "  width: 30\n"                                                    // 25
    "  ply_thickness: 0.25\n"                                          // 26
    "  stacking: \"[0/90]s\"\n"                                        // 27
    "  material: ply\n"                                                // 28
    "  section: s\n"                                                   // 29
    "  element_size: 4\n"                                              // 30
    "  refined_zone: {size: [12, 10], element_size: 1}\n"              // 31
    "  interfaces: angle-change\n"                                     // 32
    "  supports:\n"                                                    // 33
    "    window: {window: [30, 20]}\n"                                 // 34
    "impactor:\n"                                                      // 35
    "  shape: sphere\n"                                                // 36
    "  diameter: 8\n"                                                  // 37
    "  mass: 0.05 kg\n"                                                // 38
    "  velocity: 2 m/s\n"                                              // 39
    "  element_size: 1.5\n"                                            // 40
    "  material: steel\n";                                             // 41
// clang-format on

const std::string kFile = "scenes/holes.yaml";

// `base` with `from` (which must occur exactly once) replaced by `to`.
std::string edited(const std::string& base, const std::string& from, const std::string& to) {
  const auto pos = base.find(from);
  EXPECT_NE(pos, std::string::npos) << "'" << from << "' not in the base scene";
  EXPECT_EQ(base.find(from, pos + 1), std::string::npos) << "'" << from << "' occurs twice";
  std::string s = base;
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}

std::string load_error(const std::string& text, const std::vector<cfg::SceneOverride>& overrides = {}) {
  try {
    cfg::load_scene_from_string(text, kFile, overrides);
  } catch (const plyimpact::InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

// The message of the InputError that loading and meshing `text` throws (the mesh-size check runs
// before any meshing).
std::string mesh_error(const std::string& text) {
  try {
    mesh::mesh_scene(cfg::load_scene_from_string(text, kFile));
  } catch (const plyimpact::InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

std::string cycle_error(const std::string& text, const std::vector<cfg::SceneOverride>& overrides = {}) {
  try {
    const cfg::Scene scene = cfg::load_scene_from_string(text, kFile, overrides);
    const auto m = mesh::mesh_scene(scene);
    const auto model = plyimpact::model::build_model(scene, m);
    run::require_cycle_budget(scene, model, run::estimate_cycles(model));
  } catch (const plyimpact::InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

void expect_all(const std::string& message, const std::vector<std::string>& fragments) {
  for (const auto& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "expected: " << f << "\nmessage:  " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
}

// ------------------------------------------------------------------ integers

TEST(InputHoles, ElementCountBeyondIntIsRefusedNotWrapped) {
  // 4294967297 = 2^32 + 1 used to become 1 element through a cast to int.
  expect_all(load_error(edited(kBoxes, "elements: [10, 1, 1]", "elements: [4294967297, 2, 2]")),
             {"scenes/holes.yaml:18:18: mesh.boxes[0].elements[0]: element count is out of range (it would wrap "
              "around); found '4294967297'; allowed an integer in [1, 2147483647]"});
  expect_all(load_error(edited(kBoxes, "elements: [10, 1, 1]", "elements: [10, 99999999999999999999, 1]")),
             {"scenes/holes.yaml:18:22: mesh.boxes[0].elements[1]: the integer is too large to represent"});
}

// ------------------------------------------------------------------ plausible ranges

struct RangeCase {
  const char* name;
  std::string base, from, to;
  std::vector<std::string> fragments;
};

void PrintTo(const RangeCase& c, std::ostream* os) { *os << c.name; }

class ImplausibleValue : public ::testing::TestWithParam<RangeCase> {};

TEST_P(ImplausibleValue, RefusedAtItsLineWithTheRange) {
  const RangeCase& c = GetParam();
  expect_all(load_error(edited(c.base, c.from, c.to)), c.fragments);
}

const std::vector<RangeCase> kRangeCases = {
    {"huge_density", kBoxes, "RO: 7850", "RO: 1e300",
     {"scenes/holes.yaml:7:9: materials.steel.RO: 1e+300 kg/m^3 is outside the plausible range of a density",
      "found '1e300' (= 1e+300 SI); allowed RO with a magnitude in [0.01, 1e+09] kg/m^3 (SI;",
      "'Input limits' in docs/commands.md"}},
    {"tiny_density", kBoxes, "RO: 7850", "RO: 1e-300", {"scenes/holes.yaml:7:9: materials.steel.RO: 1e-300 kg/m^3"}},
    {"huge_modulus", kBoxes, "E: 210 GPa", "E: 1e300",
     {"scenes/holes.yaml:8:8: materials.steel.E: 1e+300 Pa is outside the plausible range of an elastic modulus",
      "allowed E with a magnitude in [1000, 1e+13] Pa"}},
    {"huge_velocity", kBoxes, "velocity: [0, 0, -5]", "velocity: [0, 0, -1e300]",
     {"scenes/holes.yaml:20:34: initial_velocity[0].velocity[2]: -1e+300 m/s is outside the plausible range of a "
      "velocity", "allowed velocity[2] with a magnitude of at most 100000 m/s"}},
    {"huge_box", kBoxes, "size: [0.1, 0.01, 0.01]", "size: [0.1, 0.01, 1e20]",
     {"scenes/holes.yaml:17:25: mesh.boxes[0].size[2]: 1e+20 m is outside the plausible range of a size"}},
    {"nanometre_ply", kLaminate, "ply_thickness: 0.25", "ply_thickness: 1e-6",
     {"scenes/holes.yaml:26:18: laminate.ply_thickness: 1e-09 m is outside the plausible range of a size",
      "allowed ply_thickness with a magnitude in [1e-07, 10000] m"}},
    {"huge_impact_speed", kLaminate, "velocity: 2 m/s", "velocity: 1e300 m/s",
     {"scenes/holes.yaml:39:13: impactor.velocity: 1e+300 m/s is outside the plausible range of a velocity"}},
    {"huge_strength_scene_units", kLaminate, "  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}\n",
     "  steel: {card: MAT_003, RO: 7.85e-9, E: 210 GPa, PR: 0.3, SIGY: 1e9}\n",
     {"scenes/holes.yaml:20:66: materials.steel.SIGY: 1e+15 Pa is outside the plausible range of a strength",
      "found '1e9' (= 1e+15 SI)"}},
};

INSTANTIATE_TEST_SUITE_P(InputHoles, ImplausibleValue, ::testing::ValuesIn(kRangeCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(InputHoles, PlausibleRangesAdmitRealMaterials) {
  // Independent data: handbook values at the edges of what impact models use.
  const auto& density = cfg::plausible_range(cfg::QuantityKind::density);
  for (double rho : {1.0 /* silica aerogel */, 30.0 /* foam */, 22590.0 /* osmium */, 7850.0e4 /* mass-scaled */})
    EXPECT_TRUE(cfg::is_plausible(rho, density)) << rho;
  const auto& modulus = cfg::plausible_range(cfg::QuantityKind::modulus);
  for (double e : {1e4 /* soft gel */, 1e6 /* rubber */, 1.22e12 /* diamond */}) EXPECT_TRUE(cfg::is_plausible(e, modulus)) << e;
  EXPECT_TRUE(cfg::is_plausible(1.1e4, cfg::plausible_range(cfg::QuantityKind::velocity)));  // 11 km/s orbital debris
  EXPECT_FALSE(cfg::is_plausible(std::nan(""), density));
}

// ------------------------------------------------------------------ structure

TEST(InputHoles, SecondYamlDocumentIsRefused) {
  expect_all(load_error(kBoxes + "---\ncontrol:\n  termination_time: 1\n"),
             {"scenes/holes.yaml:22:1: (top level): a second YAML document (after '---') would be ignored",
              "allowed one scene per file"});
  EXPECT_EQ(load_error("---\n" + kBoxes), "<no InputError>");  // an explicit start of the one document
}

TEST(InputHoles, PartsBesideALaminateAreRefused) {
  expect_all(load_error(kLaminate + "parts:\n  extra: {material: steel, section: s}\n"),
             {"scenes/holes.yaml:43:3: parts: parts beside a laminate would have no elements",
              "allowed a laminate without parts, or parts with mesh.boxes or mesh.file"});
}

TEST(InputHoles, OverlappingBoxesAreRefusedTouchingBoxesAreNot) {
  const std::string second = "      elements: [10, 1, 1]\n    - part: bar\n      origin: [0.05, 0, 0.005]\n"
                             "      size: [0.1, 0.01, 0.01]\n      elements: [10, 1, 1]\n";
  expect_all(load_error(edited(kBoxes, "      elements: [10, 1, 1]\n", second)),
             {"scenes/holes.yaml:19:7: mesh.boxes[1]: the box overlaps mesh.boxes[0] (part 'bar', "
              "scenes/holes.yaml:16:7)", "doubling mass and stiffness"});
  const std::string stacked = "      elements: [10, 1, 1]\n    - part: bar\n      origin: [0, 0, 0.01]\n"
                              "      size: [0.1, 0.01, 0.01]\n      elements: [10, 1, 1]\n";
  EXPECT_EQ(load_error(edited(kBoxes, "      elements: [10, 1, 1]\n", stacked)), "<no InputError>");
}

// ------------------------------------------------------------------ mesh size

TEST(InputHoles, MeshSizeEstimateMatchesTheMeshers) {
  // Exact for the plate (the mesher's own 1-D distributions) and the impactor (the scripts' block
  // structure), for a zone, a window, interfaces and a refinement level.
  for (const std::string& text :
       {kLaminate, edited(kLaminate, "  element_size: 4\n", "  element_size: 4\n  refinement_level: 1\n"),
        edited(kLaminate, "shape: sphere", "shape: hemispherical_cylinder\n  length: 14"),
        edited(kLaminate, "shape: sphere", "shape: flat_cylinder\n  length: 6"),
        edited(kLaminate, "shape: sphere", "shape: cube")}) {
    const cfg::Scene scene = cfg::load_scene_from_string(text, kFile);
    const auto estimate = mesh::estimate_mesh_size(scene);
    const auto m = mesh::mesh_scene(scene);
    // The rigid impactor keeps only its surface in the mesh, but gmsh meshes its solid, which the
    // estimate counts (DeformableImpactorEstimateIsExact checks that part); the plate is exact.
    const auto plate = mesh::estimate_mesh_size([&] {
      cfg::Scene s = scene;
      s.impactor.reset();
      return s;
    }());
    EXPECT_EQ(plate.elements, double(m.num_elements())) << text;
    EXPECT_EQ(plate.nodes, double(m.num_nodes())) << text;
    EXPECT_GT(estimate.elements, plate.elements);
  }
}

TEST(InputHoles, DeformableImpactorEstimateIsExact) {
  for (const std::string shape : {"sphere", "hemispherical_cylinder\n  length: 14", "flat_cylinder\n  length: 6", "cube"}) {
    std::string text = edited(kLaminate, "shape: sphere", "shape: " + shape);
    text = edited(text, "  material: steel\n", "  material: steel\n  rigid: false\n  section: s\n");
    const cfg::Scene scene = cfg::load_scene_from_string(text, kFile);
    cfg::Scene plate_only = scene;
    plate_only.impactor.reset();
    const double impactor = mesh::estimate_mesh_size(scene).elements - mesh::estimate_mesh_size(plate_only).elements;
    const auto m = mesh::mesh_scene(scene);
    std::size_t n = 0;
    for (int p : m.element_part) n += p == scene.impactor->part;
    EXPECT_EQ(impactor, double(n)) << shape;
  }
}

TEST(InputHoles, OversizedMeshesAreRefusedBeforeMeshing) {
  // In mm: a 1 um element size asks for 40 000 x 30 000 elements per layer (the scene that used to
  // die of std::bad_alloc inside gmsh after 10-23 s).
  expect_all(mesh_error(edited(kLaminate, "  element_size: 4\n  refined_zone: {size: [12, 10], element_size: 1}\n",
                               "  element_size: 0.001\n")),
             {"scenes/holes.yaml:30:17: laminate.element_size: the mesh would have about 4.8e+09 elements",
              "(40000 x 30000 in-plane x 4 layers (4 plies x 1 per ply)",
              "allowed at most 20000000 elements (control.max_elements, default) and 80 % of the machine's",
              "raise control.max_elements"});
  expect_all(mesh_error(edited(kLaminate, "stacking: \"[0/90]s\"", "stacking: \"[0]99999\"")),
             {"scenes/holes.yaml:27:13: laminate.stacking: the mesh would have about", "x 99999 layers (99999 plies"});
  expect_all(mesh_error(edited(kLaminate, "  element_size: 1.5\n", "  element_size: 0.001\n")),
             {"scenes/holes.yaml:40:17: impactor.element_size: the mesh would have about",
              "impactor: 6284 elements per quarter circumference"});
  expect_all(mesh_error(edited(kBoxes, "elements: [10, 1, 1]", "elements: [100000, 1000, 1000]")),
             {"scenes/holes.yaml:18:17: mesh.boxes[0].elements: the mesh would have about 1e+11 elements"});
  // The limit is the user's to raise; the estimate alone decides, no mesh is made here.
  cfg::Scene fine = cfg::load_scene_from_string(edited(kBoxes, "elements: [10, 1, 1]", "elements: [3000, 3000, 3]"), kFile);
  const auto estimate = mesh::estimate_mesh_size(fine);
  EXPECT_EQ(estimate.elements, 2.7e7);
  EXPECT_THROW(mesh::require_mesh_fits(fine, estimate, 0), plyimpact::InputError);
  fine.control.max_elements = 30000000;
  EXPECT_NO_THROW(mesh::require_mesh_fits(fine, estimate, 0));
  // Memory: 80 % of the machine, unless the user states the limit.
  fine.control.max_elements = 0;
  fine.boxes[0].elements = {100, 100, 100};
  const auto small = mesh::estimate_mesh_size(fine);
  expect_all([&] {
    try {
      mesh::require_mesh_fits(fine, small, small.bytes);
    } catch (const plyimpact::InputError& e) {
      return std::string(e.what());
    }
    return std::string("<no InputError>");
  }(), {"found more than this machine holds", "and 80 % of the machine's"});
  EXPECT_NO_THROW(mesh::require_mesh_fits(fine, small, 2 * small.bytes));
}

// ------------------------------------------------------------------ cycle count

TEST(InputHoles, CycleEstimateIsTheSolversInitialStep) {
  // Independent answer: the solver's own first stable step (same element length V / A_max, same
  // wave speed, TSSFAC), to round-off.
  const cfg::Scene scene = cfg::load_scene_from_string(edited(kBoxes, "size: [0.1, 0.01, 0.01]", "size: [0.1, 0.013, 0.007]"), kFile);
  const auto m = mesh::mesh_scene(scene);
  const auto model = plyimpact::model::build_model(scene, m);
  const auto estimate = run::estimate_cycles(model);
  const plyimpact::solver::Solver solver(model);
  EXPECT_NEAR(estimate.dt, solver.state().dt_next_half, 1e-12 * estimate.dt);
  // L = 0.007 m (the thinnest direction of the 10 x 13 x 7 mm elements), c = sqrt(E (1 - nu) / (rho (1 + nu)(1 - 2 nu))).
  const double c = std::sqrt(210e9 * 0.7 / (7850 * 1.3 * 0.4));
  EXPECT_NEAR(estimate.dt, 0.9 * 0.007 / c, 1e-12 * estimate.dt);
  EXPECT_EQ(estimate.cycles, std::ceil(1e-5 / estimate.dt));
}

TEST(InputHoles, EndlessRunsAreRefusedAtTheKeyThatMakesThem) {
  expect_all(cycle_error(edited(kBoxes, "termination_time: 1.0e-5", "termination_time: 1.0e-5\n  tssfac: 1e-12")),
             {"scenes/holes.yaml:4:11: control.tssfac: the run would need about", "TSSFAC 1e-12",
              "allowed at most 1e+08 cycles (control.cycle_limit, default)"});
  expect_all(cycle_error(edited(kBoxes, "termination_time: 1.0e-5", "termination_time: 1000")),
             {"scenes/holes.yaml:3:21: control.termination_time: the run would need about", "e+08 cycles"});
  // A wave speed no solid has: the density (within its plausible range) against the modulus.
  expect_all(cycle_error(edited(edited(edited(kBoxes, "RO: 7850", "RO: 0.02"), "E: 210 GPa", "E: 1e13"),
                                "termination_time: 1.0e-5", "termination_time: 0.1")),
             {"scenes/holes.yaml:7:9: materials.steel.RO: the run would need about"});
  // Raised limit, or a run that stops early at max_cycles (ENDCYC): accepted.
  EXPECT_EQ(cycle_error(edited(kBoxes, "termination_time: 1.0e-5", "termination_time: 1.0e-5\n  tssfac: 1e-8\n  cycle_limit: 1000000000")),
            "<no InputError>");
  EXPECT_EQ(cycle_error(edited(kBoxes, "termination_time: 1.0e-5", "termination_time: 1.0e-5\n  tssfac: 1e-12\n  max_cycles: 1000")),
            "<no InputError>");
}

TEST(InputHoles, ProgressDurationsAreNeverNegativeOrWrapped) {
  EXPECT_EQ(run::format_duration(12.34), "12.3s");
  EXPECT_EQ(run::format_duration(125), "2m05s");
  EXPECT_EQ(run::format_duration(-1), "?");
  EXPECT_EQ(run::format_duration(std::numeric_limits<double>::infinity()), "?");
  EXPECT_EQ(run::format_duration(std::nan("")), "?");
  EXPECT_EQ(run::format_duration(4.5e150), "1.25e+147h");  // the RO 1e-300 run's ETA
}

// ------------------------------------------------------------------ overrides and the command line

TEST(InputHoles, OverridesGoThroughTheSameChecks) {
  const auto set = [](const char* text) { return std::vector<cfg::SceneOverride>{cfg::parse_set_argument(text)}; };
  expect_all(load_error(kBoxes, set("materials.steel.RO=1e300")),
             {"--set materials.steel.RO=1e300: materials.steel.RO: 1e+300 kg/m^3 is outside the plausible range"});
  expect_all(load_error(kBoxes, set("mesh.boxes[0].elements=[4294967297, 2, 2]")),
             {"mesh.boxes[0].elements[0]: element count is out of range"});
  expect_all(cycle_error(kBoxes, set("control.tssfac=1e-12")),
             {"--set control.tssfac=1e-12: control.tssfac: the run would need about"});
}

TEST(InputHoles, RefusedRunsWriteNothingAndExitAsInputErrors) {
  const auto dir = std::filesystem::path(PLYIMPACT_BINARY_DIR) / "input_holes";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto scene = dir / "endless.yaml";
  std::ofstream(scene) << edited(kBoxes, "termination_time: 1.0e-5", "termination_time: 1.0e-5\n  tssfac: 1e-12");
  const std::string out_dir = (dir / "out").string();
  const struct {
    std::vector<std::string> args;
    std::string fragment;
  } cases[] = {
      {{"run", scene.string(), "-o", out_dir}, "endless.yaml:4:11: control.tssfac: the run would need"},
      {{"check", scene.string()}, "endless.yaml:4:11: control.tssfac: the run would need"},
      {{"run", scene.string(), "-o", out_dir, "--set", "control.tssfac=0.9", "--set",
        "mesh.boxes[0].elements=[100000, 1000, 1000]"},
       "mesh.boxes[0].elements: the mesh would have about 1e+11 elements"},
  };
  for (const auto& c : cases) {
    std::ostringstream out, err;
    EXPECT_EQ(plyimpact::app::run_application(c.args, out, err), 1) << err.str();
    EXPECT_NE(err.str().find(c.fragment), std::string::npos) << err.str();
    EXPECT_FALSE(std::filesystem::exists(out_dir));
  }
}

}  // namespace
