// Determinism: one and two OpenMP threads give bit-identical results (the element schedule fixes
// the order in which forces are summed at every node, and all reductions run in chunk order).
// The model is large enough (>= 8192 elements) for the element pass to run in parallel.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>

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

}  // namespace
}  // namespace plyimpact
