// Determinism: one and two OpenMP threads give bit-identical results (the element schedule fixes
// the order in which forces are summed at every node, and all reductions run in chunk order).
// The models are large enough (>= 8192 elements) for the element pass to run in parallel: a
// cantilevered cross-ply plate, and an impact that brings contact, erosion and a rigid body in.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <iostream>
#include <memory>

#include "support.hpp"

namespace plyimpact {
namespace {

solver::State run_with_threads(const model::Model& model, int threads) {
  omp_set_num_threads(threads);
  solver::Solver s(model);
  for (int i = 0; i < 30; ++i) s.step();
  return s.state();
}

TEST(Threads, OneAndTwoThreadsAreBitIdentical) {
  model::Model model = test::model_from_yaml(
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      "  ply: {card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1,0,0], D: [0,1,0]}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\nparts:\n  p0: {material: ply, section: s}\n  p90: {material: ply, section: s, beta: 90}\n"
      "mesh:\n  boxes:\n    - {part: p0, size: [0.04, 0.02, 0.002], elements: [32, 16, 8]}\n"
      "    - {part: p90, origin: [0, 0, 0.002], size: [0.04, 0.02, 0.002], elements: [32, 16, 8]}\n"
      "node_sets:\n  edge: {plane: {axis: x, value: 0}}\nboundary_conditions:\n  - {node_set: edge, fix: [x, y, z]}\n");
  ASSERT_GE(model.num_elements(), 8192u);
  for (std::size_t n = 0; n < model.num_nodes(); ++n) model.v0[3 * n + 2] = 10.0 * model.X[3 * n] / 0.04;
  const solver::State a = run_with_threads(model, 1);
  const solver::State b = run_with_threads(model, 2);
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

// A rigid steel block (*MAT_020, a rigid body) strikes a *MAT_054 plate (strains to erosion set
// low) through eroding penalty contact: the contact forces, the erosion and the surface rebuild it
// triggers, and the rigid body all run on what the parallel element pass produced. The run must
// really erode elements and move the body, or it would not test their determinism.
// `control`: extra control keys (mass scaling).
void expect_impact_bit_identical(const std::string& control) {
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1" + control + "}\nmaterials:\n"
      "  ply: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], XT: 2.0e9, XC: 1.2e9,"
      " YT: 50e6, YC: 200e6, SC: 70e6, DFAILT: 0.004, DFAILC: -0.004, DFAILM: 0.004, DFAILS: 0.004}\n"
      "  rig: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
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
  }
  for (std::size_t e = 0; e < model.blocks[0].size(); ++e)
    ASSERT_EQ(a->element_alive(0, Index(e)), b->element_alive(0, Index(e))) << "element " << e;
  EXPECT_EQ(0, std::memcmp(&a->rigid_bodies()[0], &b->rigid_bodies()[0], sizeof(solver::RigidBodyState)));
  EXPECT_EQ(a->balance().total(), b->balance().total());
  EXPECT_EQ(a->balance().value("contact"), b->balance().value("contact"));
  EXPECT_EQ(sa.internal_energy, sb.internal_energy);
  EXPECT_EQ(sa.dt_next_half, sb.dt_next_half);
}

TEST(Threads, ImpactWithContactErosionAndRigidBodyIsBitIdentical) { expect_impact_bit_identical(""); }

// The same with mass scaling (solver/mass_scaling): the plate's 4.9e-8 s elements scaled to 6e-8 s.
TEST(Threads, MassScaledImpactIsBitIdentical) { expect_impact_bit_identical(", dt2ms: -6e-8"); }

}  // namespace
}  // namespace plyimpact
