// Determinism: one and two OpenMP threads give bit-identical results (the element schedule fixes
// the order in which forces are summed at every node, the contact scatters its springs in node
// order after its parallel search, interfaces share no node, and all reductions run in a fixed
// order). Models: a cantilevered cross-ply plate, an impact that brings contact, erosion and a rigid
// body in, and a small laminate (below the old 8192-element threshold) with all of these and
// tiebreak interfaces, run through `plyimpact run` so the whole history and final frames compare.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/application.hpp"
#include "solver/rigid_body.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

// review_every > 0: the element pass's chunk plan is reviewed every that many passes and replaced
// by the new one whatever its simulated gain, so that threads and node chunks change hands.
solver::State run_with_threads(const model::Model& model, int threads, long review_every = 0) {
  omp_set_num_threads(threads);
  solver::Solver s(model);
  if (review_every > 0) s.set_chunk_plan_review(review_every, -1.0);
  for (int i = 0; i < 30; ++i) s.step();
  return s.state();
}

model::Model cross_ply_plate() {
  model::Model model = test::model_from_yaml(
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      "  ply: {card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1,0,0], D: [0,1,0]}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\nparts:\n  p0: {material: ply, section: s}\n  p90: {material: ply, section: s, beta: 90}\n"
      "mesh:\n  boxes:\n    - {part: p0, size: [0.04, 0.02, 0.002], elements: [32, 16, 8]}\n"
      "    - {part: p90, origin: [0, 0, 0.002], size: [0.04, 0.02, 0.002], elements: [32, 16, 8]}\n"
      "node_sets:\n  edge: {plane: {axis: x, value: 0}}\nboundary_conditions:\n  - {node_set: edge, fix: [x, y, z]}\n");
  for (std::size_t n = 0; n < model.num_nodes(); ++n) model.v0[3 * n + 2] = 10.0 * model.X[3 * n] / 0.04;
  return model;
}

void expect_same_state(const solver::State& a, const solver::State& b) {
  ASSERT_EQ(a.x.size(), b.x.size());
  EXPECT_EQ(0, std::memcmp(a.x.data(), b.x.data(), a.x.size() * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(double)));
  for (std::size_t blk = 0; blk < a.blocks.size(); ++blk)
    EXPECT_EQ(0, std::memcmp(a.blocks[blk].stress.data(), b.blocks[blk].stress.data(),
                             a.blocks[blk].stress.size() * sizeof(double)));
  EXPECT_EQ(a.internal_energy, b.internal_energy);
  EXPECT_EQ(a.hourglass_energy, b.hourglass_energy);
  EXPECT_EQ(a.dt_next_half, b.dt_next_half);
}

TEST(Threads, OneAndTwoThreadsAreBitIdentical) {
  const model::Model model = cross_ply_plate();
  ASSERT_GE(model.num_elements(), 8192u);
  expect_same_state(run_with_threads(model, 1), run_with_threads(model, 2));
}

// The plan of the parallel element pass (solver/chunk_plan) is made anew from the measured chunk
// times at every pass: which thread runs which chunks, in which order, and which thread updates which
// nodes, change from cycle to cycle. The results may not.
TEST(Threads, ChunkPlanMadeAnewEveryPassIsBitIdentical) {
  const model::Model model = cross_ply_plate();
  expect_same_state(run_with_threads(model, 1), run_with_threads(model, 2, 1));
}

// A spinning rigid body of 2,197 nodes (above RigidBodies::kParallelMinNodes, so two threads share
// the placement of its nodes) beside a deformable block that makes the model parallel: its nodes'
// positions and velocities, and its state, are bit-identical on one and two threads. The spin
// (omega_y from opposite x velocities of the top and bottom faces) turns the body in every cycle.
TEST(Threads, ManyNodeRigidBodyIsPlacedBitIdentically) {
  const model::Model model = test::model_from_yaml(
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      "  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "  rig: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1}\nparts:\n  body: {material: rig, section: s}\n  plate: {material: steel, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: body, size: [0.012, 0.012, 0.012], elements: [12, 12, 12]}\n"
      "    - {part: plate, origin: [0.1, 0, 0], size: [0.032, 0.032, 0.002], elements: [32, 32, 2]}\n"
      "node_sets:\n  top: {plane: {axis: z, value: 0.012}}\n  bottom: {plane: {axis: z, value: 0}}\n"
      "initial_velocity:\n  - {node_set: top, velocity: [20, 0, 0]}\n  - {node_set: bottom, velocity: [-20, 0, 0]}\n",
      "rigid_threads.yaml");
  ASSERT_EQ(model.rigid_bodies.size(), 1u);
  ASSERT_GE(long(model.rigid_bodies[0].nodes.size()), solver::RigidBodies::kParallelMinNodes);
  ASSERT_GE(model.num_elements(), 1024u + 1728u);
  omp_set_num_threads(1);
  solver::Solver one(model);
  omp_set_num_threads(2);
  solver::Solver two(model);
  for (int i = 0; i < 30; ++i) {
    omp_set_num_threads(1);
    one.step();
    omp_set_num_threads(2);
    two.step();
  }
  ASSERT_GT(std::abs(one.rigid_bodies()[0].omega[1]), 0.0) << "the body does not spin";
  EXPECT_EQ(0, std::memcmp(one.state().x.data(), two.state().x.data(), one.state().x.size() * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(one.state().v.data(), two.state().v.data(), one.state().v.size() * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(&one.rigid_bodies()[0], &two.rigid_bodies()[0], sizeof(solver::RigidBodyState)));
}

// A rigid steel block (*MAT_020, a rigid body) strikes a *MAT_054 plate (strains to erosion set
// low) through eroding penalty contact: the contact forces, the erosion and the surface rebuild it
// triggers, and the rigid body all run on what the parallel element pass produced. The run must
// really erode elements and move the body, or it would not test their determinism.
// IHQ 4 and IHQ 6 (the default scene's form): both accumulate hourglass forces per element.
// `control`: extra control keys (mass scaling).
void expect_impact_bit_identical(int ihq, const std::string& control = "") {
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1" + control + "}\nmaterials:\n"
      "  ply: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], XT: 2.0e9, XC: 1.2e9,"
      " YT: 50e6, YC: 200e6, SC: 70e6, DFAILT: 0.004, DFAILC: -0.004, DFAILM: 0.004, DFAILS: 0.004}\n"
      "  rig: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: " + std::to_string(ihq) + "}\n"
      "parts:\n  plate: {material: ply, section: s}\n  block: {material: rig, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: plate, origin: [-0.016, -0.016, -0.002], size: [0.032, 0.032, 0.002], elements: [64, 64, 2]}\n"
      "    - {part: block, origin: [-0.002, -0.002, 5.0e-5], size: [0.004, 0.004, 0.002], elements: [8, 8, 4]}\n"
      "node_sets:\n  edge: {plane: {axis: x, value: -0.016}}\n"
      "boundary_conditions:\n  - {node_set: edge, fix: [x, y, z]}\n"
      "initial_velocity:\n  - {part: block, velocity: [3, 1, -150]}\n"
      "contacts:\n  - {name: impact, type: eroding_surface_to_surface, surfaces: [block, plate], SOFT: 1}\n";
  const model::Model model = test::model_from_yaml(yaml, "threads_impact.yaml");
  ASSERT_GE(model.num_elements(), 8192u);
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    auto s = std::make_unique<solver::Solver>(model);
    for (int i = 0; i < 150; ++i) s->step();
    return s;
  };
  const auto a = run(1);
  const auto b = run(2);
  long eroded = 0;
  for (std::size_t e = 0; e < model.blocks[0].size(); ++e) eroded += a->element_alive(0, Index(e)) ? 0 : 1;
  std::cout << "impact: " << eroded << " plate elements eroded, body vz " << a->rigid_bodies()[0].v[2]
            << " m/s, contact energy " << a->balance().value("contact") << " J\n";
  ASSERT_GT(eroded, 0) << "no erosion: the run does not exercise it";
  ASSERT_GT(a->rigid_bodies()[0].v[2], -150.0 + 1.0) << "the body was not slowed by the contact";
  const auto& sa = a->state();
  const auto& sb = b->state();
  EXPECT_EQ(0, std::memcmp(sa.x.data(), sb.x.data(), sa.x.size() * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(sa.v.data(), sb.v.data(), sa.v.size() * sizeof(double)));
  for (std::size_t blk = 0; blk < sa.blocks.size(); ++blk) {
    EXPECT_EQ(0, std::memcmp(sa.blocks[blk].stress.data(), sb.blocks[blk].stress.data(),
                             sa.blocks[blk].stress.size() * sizeof(double)));
    EXPECT_EQ(0, std::memcmp(sa.blocks[blk].history.data(), sb.blocks[blk].history.data(),
                             sa.blocks[blk].history.size() * sizeof(double)));
    EXPECT_EQ(0, std::memcmp(sa.blocks[blk].hourglass.data(), sb.blocks[blk].hourglass.data(),
                             sa.blocks[blk].hourglass.size() * sizeof(double)));
  }
  EXPECT_EQ(sa.hourglass_energy, sb.hourglass_energy);
  for (std::size_t e = 0; e < model.blocks[0].size(); ++e)
    ASSERT_EQ(a->element_alive(0, Index(e)), b->element_alive(0, Index(e))) << "element " << e;
  EXPECT_EQ(0, std::memcmp(&a->rigid_bodies()[0], &b->rigid_bodies()[0], sizeof(solver::RigidBodyState)));
  EXPECT_EQ(a->balance().total(), b->balance().total());
  EXPECT_EQ(a->balance().value("contact"), b->balance().value("contact"));
  EXPECT_EQ(sa.internal_energy, sb.internal_energy);
  EXPECT_EQ(sa.dt_next_half, sb.dt_next_half);
}

TEST(Threads, ImpactWithContactErosionAndRigidBodyIsBitIdentical) { expect_impact_bit_identical(4); }
TEST(Threads, ImpactWithAssumedStrainHourglassIsBitIdentical) { expect_impact_bit_identical(6); }
namespace fs = std::filesystem;

std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The last value of a history.csv column.
double last_value(const std::string& csv, const std::string& column) {
  std::istringstream in(csv);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::istringstream h(header), l(last);
  std::string name, value;
  while (std::getline(h, name, ',') && std::getline(l, value, ','))
    if (name == column) return std::stod(value);
  ADD_FAILURE() << "no column " << column;
  return 0;
}

// The largest value of a history.csv column.
double max_value(const std::string& csv, const std::string& column) {
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  int index = -1, k = 0;
  std::istringstream h(header);
  for (std::string name; std::getline(h, name, ','); ++k)
    if (name == column) index = k;
  if (index < 0) ADD_FAILURE() << "no column " << column;
  double best = -1e300;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::string value;
    int i = 0;
    while (i <= index && std::getline(l, value, ',')) ++i;
    if (i > index) best = std::max(best, std::stod(value));
  }
  return best;
}

// A [0/90]s laminate of *MAT_054 plies (1600 elements: below the 8192 elements from which the
// solver used to go parallel) with tiebreak (OPTION 9) on its two angle-change interfaces and a
// bonded middle interface, struck by a rigid hemispherical tup through eroding contact; strains to
// failure and interface strengths set low so that within 414 cycles elements erode and the
// interfaces dissipate energy. The whole history and every frame (plies, tup, interfaces) of one and
// two threads must be the same bytes. `section`: the plies' section (one-point, or ELFORM -2, whose
// pass sums over its eight points in a fixed order).
void expect_small_laminate_bit_identical(const std::string& section) {
  const std::string scene =
      "units: mm-t-s-MPa\ncontrol: {termination_time: 8.0e-6}\noutput: {interval: 4.0e-6, history_interval: 1.0e-7}\n"
      "materials:\n"
      "  ply: {card: MAT_054, RO: 1550 kg/m^3, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.01895, PRCA: 0.01895,\n"
      "        PRCB: 0.53, GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0],\n"
      "        XT: 2.2 GPa, XC: 1.2 GPa, YT: 0.045 GPa, YC: 0.28 GPa, SC: 0.045 GPa, SOFT: 1, CRIT: 54, BETA: 1,\n"
      "        DFAILT: 0.003, DFAILC: -0.003, DFAILM: 0.003, DFAILS: 0.003}\n"
      "  steel: {card: MAT_001, RO: 7857 kg/m^3, E: 206.7 GPa, PR: 0.3}\n"
      "sections:\n  ply: " + section + "\n"
      "laminate:\n  length: 20\n  width: 20\n  ply_thickness: 0.25\n  stacking: \"[0/90]s\"\n  material: ply\n"
      "  section: ply\n  element_size: 1\n"
      "  interfaces: {select: angle-change, model: tiebreak, OPTION: 9, NFLS: 20 MPa, SFLS: 20 MPa, PARAM: 1,\n"
      "               ERATEN: 200 J/m^2, ERATES: 300 J/m^2, CT2CN: 1, CN: 100 kN/mm^3}\n"
      "  supports:\n    window: {window: [16, 16]}\n"
      "impactor: {shape: hemispherical_cylinder, diameter: 6, length: 6, mass: 0.05 kg, gap: 0.001, velocity: 30 m/s,\n"
      "           element_size: 1, rigid: true, material: steel}\n"
      "contacts:\n  - {name: tup_plies, type: eroding_surface_to_surface, SOFT: 1,\n"
      "     surfaces: [impactor, [ply_1_0, ply_2_90, ply_3_90, ply_4_0]]}\n";
  const fs::path dir = fs::temp_directory_path() / ("plyimpact_threads_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "small_impact.yaml") << scene;
  auto run = [&](int threads) {
    const fs::path out = dir / ("threads_" + std::to_string(threads));
    std::ostringstream o, e;
    const int code = app::run_application(
        {"run", (dir / "small_impact.yaml").string(), "--threads", std::to_string(threads), "-o", out.string()}, o, e);
    EXPECT_EQ(0, code) << e.str() << o.str();
    return out;
  };
  const fs::path one = run(1), two = run(2);
  const std::string summary = file_bytes(two / "summary.json");
  EXPECT_NE(summary.find("\"threads\": 2"), std::string::npos) << "the 2-thread run did not run on 2 threads";
  EXPECT_NE(summary.find("\"elements\": 1600"), std::string::npos) << summary.substr(0, 400);
  const std::string history = file_bytes(one / "history.csv");
  // The run must exercise what it claims to: contact force, erosion, interface damage, the body slowed.
  EXPECT_GT(max_value(history, "contact_tup_plies_normal"), 0.0);
  EXPECT_GT(last_value(history, "interface_dissipated_energy"), 0.0);
  EXPECT_GT(last_value(history, "rigid_impactor_vz"), -30.0);
  EXPECT_NE(summary.find("\"eroded_elements\": "), std::string::npos);
  EXPECT_EQ(summary.find("\"eroded_elements\": 0,"), std::string::npos) << "no element eroded";
  EXPECT_EQ(history, file_bytes(two / "history.csv"));
  int frames = 0;
  for (const auto& entry : fs::recursive_directory_iterator(one)) {
    const fs::path rel = fs::relative(entry.path(), one);
    if (!entry.is_regular_file() || entry.path().extension() != ".vtu") continue;
    ++frames;
    EXPECT_EQ(file_bytes(entry.path()), file_bytes(two / rel)) << rel;
  }
  EXPECT_GE(frames, 6) << "plies, tup and interfaces at t = 0, 4 and 8 us";
  fs::remove_all(dir);
}

TEST(Threads, SmallLaminateImpactRunIsBitIdentical) { expect_small_laminate_bit_identical("{ELFORM: 1, IHQ: 2, QM: 0.1}"); }
TEST(Threads, SmallLaminateImpactWithFullyIntegratedPliesIsBitIdentical) {
  expect_small_laminate_bit_identical("{ELFORM: -2}");
}

// The first impact with mass scaling (solver/mass_scaling): the plate's 4.9e-8 s elements scaled to 6e-8 s.
TEST(Threads, MassScaledImpactIsBitIdentical) { expect_impact_bit_identical(4, ", dt2ms: -6e-8"); }

}  // namespace
}  // namespace plyimpact
