// The parallel element pass's plan (solver/chunk_plan): which thread runs which element chunks, in
// which order. What must hold whatever the costs it is given: every chunk runs once, on the thread
// whose contiguous range holds it, and threads that follow the plan, each waiting before a chunk
// for that chunk's lower-colour neighbours, never wait on each other in a cycle. What it is for:
// where the split between two threads falls between two plates sharing nodes (two plies of one
// angle meshed as one), the thread below runs the chunks the other waits for first, and a pass
// takes half the work on each thread.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "solver/chunk_plan.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

// Four 32 x 32 x 1 plates of steel, 4 chunks of 256 elements each; the middle two touch (merged
// nodes), the others stand apart.
model::Model four_plates() {
  return test::model_from_yaml(
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      "  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1}\nparts:\n  a: {material: steel, section: s}\n  b: {material: steel, section: s}\n"
      "  c: {material: steel, section: s}\n  d: {material: steel, section: s}\n"
      "mesh:\n  boxes:\n"
      "    - {part: a, origin: [0, 0, 0], size: [0.032, 0.032, 0.001], elements: [32, 32, 1]}\n"
      "    - {part: b, origin: [0, 0, 0.002], size: [0.032, 0.032, 0.001], elements: [32, 32, 1]}\n"
      "    - {part: c, origin: [0, 0, 0.003], size: [0.032, 0.032, 0.001], elements: [32, 32, 1]}\n"
      "    - {part: d, origin: [0, 0, 0.005], size: [0.032, 0.032, 0.001], elements: [32, 32, 1]}\n",
      "four_plates.yaml");
}

// Runs the plan's orders with the waits of the element pass, the next thread to move drawn at
// random: any timing the threads may have. False if at some point no thread can move.
bool runs_to_the_end(const solver::ChunkPlan& plan, std::mt19937& rng) {
  const int nt = plan.threads();
  std::vector<std::size_t> next(std::size_t(nt), 0);
  std::vector<char> done(plan.num_chunks(), 0);
  for (std::size_t finished = 0; finished < plan.num_chunks();) {
    std::vector<int> movable;
    for (int t = 0; t < nt; ++t) {
      const auto order = plan.order(t);
      if (next[std::size_t(t)] == order.size()) continue;
      const auto preds = plan.predecessors(order[next[std::size_t(t)]]);
      if (std::all_of(preds.begin(), preds.end(), [&](int p) { return done[std::size_t(p)] != 0; })) movable.push_back(t);
    }
    if (movable.empty()) return false;
    const int t = movable[std::uniform_int_distribution<std::size_t>(0, movable.size() - 1)(rng)];
    done[std::size_t(plan.order(t)[next[std::size_t(t)]++])] = 1;
    ++finished;
  }
  return true;
}

TEST(ChunkPlan, EveryChunkOnceOnTheThreadOfItsRangeAndNoDeadlockForAnyCosts) {
  const model::Model model = four_plates();
  solver::ChunkPlan plan(model);
  ASSERT_EQ(plan.num_chunks(), 16u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> cost_of(0.0, 10.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int nt = 2 + trial % 3;
    std::vector<double> cost(plan.num_chunks());
    for (double& c : cost) c = trial % 7 == 0 ? 0.0 : cost_of(rng);  // all zero now and then
    plan.plan(nt, cost);
    ASSERT_EQ(plan.threads(), nt);
    const auto bounds = plan.bounds();
    ASSERT_EQ(bounds.size(), std::size_t(nt) + 1);
    EXPECT_EQ(bounds.front(), 0);
    EXPECT_EQ(bounds.back(), long(plan.num_chunks()));
    std::vector<int> seen(plan.num_chunks(), 0);
    for (int t = 0; t < nt; ++t) {
      EXPECT_LE(bounds[std::size_t(t)], bounds[std::size_t(t) + 1]);
      for (int c : plan.order(t)) {
        ++seen[std::size_t(c)];
        EXPECT_GE(c, bounds[std::size_t(t)]) << "trial " << trial;
        EXPECT_LT(c, bounds[std::size_t(t) + 1]) << "trial " << trial;
      }
    }
    for (std::size_t c = 0; c < seen.size(); ++c) EXPECT_EQ(seen[c], 1) << "chunk " << c << ", trial " << trial;
    for (int run = 0; run < 5; ++run) ASSERT_TRUE(runs_to_the_end(plan, rng)) << "deadlock, trial " << trial;
  }
}

TEST(ChunkPlan, PredecessorsAreTheLowerColourChunksSharingANode) {
  const model::Model model = four_plates();
  solver::ChunkPlan plan(model);
  const auto& schedule = model.schedule;
  std::vector<int> color(schedule.chunks.size());
  for (std::size_t k = 0; k < schedule.colors.size(); ++k)
    for (int c : schedule.colors[k]) color[std::size_t(c)] = int(k);
  auto nodes_of = [&](std::size_t c) {
    const auto& ch = schedule.chunks[c];
    const auto& conn = model.blocks[std::size_t(ch.block)].conn;
    std::vector<Index> nodes(conn.begin() + 8 * std::ptrdiff_t(ch.begin), conn.begin() + 8 * std::ptrdiff_t(ch.end));
    std::sort(nodes.begin(), nodes.end());
    return nodes;
  };
  for (std::size_t a = 0; a < plan.num_chunks(); ++a) {
    std::vector<int> expected;
    for (std::size_t b = 0; b < plan.num_chunks(); ++b) {
      if (color[b] >= color[a]) continue;
      const auto na = nodes_of(a), nb = nodes_of(b);
      std::vector<Index> shared;
      std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(shared));
      if (!shared.empty()) expected.push_back(int(b));
    }
    const auto got = plan.predecessors(int(a));
    EXPECT_EQ(std::vector<int>(got.begin(), got.end()), expected) << "chunk " << a;
  }
  // Plates b and c share their common face, so some chunk of c waits for one of b.
  bool c_waits_for_b = false;
  for (int c = 8; c < 12; ++c)
    for (int p : plan.predecessors(c)) c_waits_for_b = c_waits_for_b || (p >= 4 && p < 8);
  EXPECT_TRUE(c_waits_for_b);
}

// Equal costs, two threads: the split falls between plates b and c, and c's chunks wait for b's.
// With b's chunks first on thread 0 and d's first on thread 1, neither thread idles: the pass takes
// exactly the 8 chunks each thread owns. (Colour by colour, thread 0 would run b's second-colour
// chunks after a's, and thread 1 would wait for them.)
TEST(ChunkPlan, TheChunksAnotherThreadWaitsForRunFirst) {
  const model::Model model = four_plates();
  solver::ChunkPlan plan(model);
  const std::vector<double> cost(plan.num_chunks(), 1.0);
  plan.plan(2, cost);
  EXPECT_EQ(plan.bounds()[1], 8);
  EXPECT_DOUBLE_EQ(plan.simulated_span(cost), 8.0);
  const auto first = plan.order(0);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_GE(first[k], 4) << "thread 0 runs plate b's chunks first";
}

// Costs, not counts: when plate a's chunks cost eight times the others' (fully integrated
// elements), the best contiguous split gives thread 0 three of a's chunks (24 units) and thread 1
// the fourth and the other plates' (20 units): a pass of 24 units, where even ranges of 8 chunks
// would give thread 0 all of plate a and b (36 units).
TEST(ChunkPlan, RangesShareTheCostNotTheChunkCount) {
  const model::Model model = four_plates();
  solver::ChunkPlan plan(model);
  std::vector<double> cost(plan.num_chunks(), 1.0);
  for (int c = 0; c < 4; ++c) cost[std::size_t(c)] = 8.0;
  plan.plan(2, cost);
  EXPECT_EQ(plan.bounds()[1], 3);
  EXPECT_DOUBLE_EQ(plan.simulated_span(cost), 24.0);
}

// A plan is replaced only when the new one is clearly faster: with the same costs nothing changes,
// with costs that move the balance it does.
TEST(ChunkPlan, ReplacedOnlyForAGain) {
  const model::Model model = four_plates();
  solver::ChunkPlan plan(model);
  std::vector<double> cost(plan.num_chunks(), 1.0);
  EXPECT_TRUE(plan.plan(2, cost));
  EXPECT_FALSE(plan.plan(2, cost, 0.02));
  for (int c = 0; c < 4; ++c) cost[std::size_t(c)] = 8.0;
  EXPECT_TRUE(plan.plan(2, cost, 0.02));
  EXPECT_EQ(plan.bounds()[1], 3);
}

}  // namespace
}  // namespace plyimpact
