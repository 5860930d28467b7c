// The node update's split over threads (solver/node_chunk_owners): every node chunk is updated by
// exactly one thread, and a node goes to the thread that computes its elements in the element
// pass, or, for a rigid body's node, to the thread that places it. Model: a rigid block followed by
// two deformable plates of equal size, unmerged, so the node numbers run body, plate 1, plate 2 and
// the element pass gives plate 1 to thread 0 and plate 2 to thread 1 of two.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "solver/node_chunk_owners.hpp"
#include "solver/rigid_body.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

model::Model body_and_two_plates() {
  return test::model_from_yaml(
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      "  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "  rig: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1}\nparts:\n  body: {material: rig, section: s}\n"
      "  plate1: {material: steel, section: s}\n  plate2: {material: steel, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: body, size: [0.012, 0.012, 0.012], elements: [12, 12, 12]}\n"
      "    - {part: plate1, origin: [0.1, 0, 0], size: [0.032, 0.032, 0.002], elements: [32, 32, 1]}\n"
      "    - {part: plate2, origin: [0.2, 0, 0], size: [0.032, 0.032, 0.002], elements: [32, 32, 1]}\n",
      "node_owners.yaml");
}

TEST(NodeChunkOwners, NodesGoToTheThreadOfTheirElementsOrOfTheirBodysPlacement) {
  const model::Model model = body_and_two_plates();
  ASSERT_EQ(model.rigid_bodies.size(), 1u);
  const long body_nodes = long(model.rigid_bodies[0].nodes.size());
  ASSERT_EQ(body_nodes, 13 * 13 * 13);
  ASSERT_GE(body_nodes, solver::RigidBodies::kParallelMinNodes);  // placed by both threads
  ASSERT_EQ(model.schedule.chunks.size() % 2, 0u);
  const std::size_t plate_nodes = 33 * 33 * 2;
  ASSERT_EQ(model.num_nodes(), std::size_t(body_nodes) + 2 * plate_nodes);
  solver::NodeChunkOwners owners(model, 1);  // one node per chunk: every node's owner is visible
  const auto& table = owners.for_threads(2);
  ASSERT_EQ(table.size(), 2u);
  std::vector<int> owner(model.num_nodes(), -1);
  for (int t = 0; t < 2; ++t)
    for (long c : table[std::size_t(t)]) {
      ASSERT_EQ(owner[std::size_t(c)], -1) << "node " << c << " updated by two threads";
      owner[std::size_t(c)] = t;
    }
  const auto& nodes = model.rigid_bodies[0].nodes;
  for (long k = 0; k < body_nodes; ++k)
    EXPECT_EQ(owner[std::size_t(nodes[std::size_t(k)])], k < body_nodes / 2 ? 0 : 1) << "body node " << k;
  for (std::size_t n = std::size_t(body_nodes); n < model.num_nodes(); ++n)
    EXPECT_EQ(owner[n], n < std::size_t(body_nodes) + plate_nodes ? 0 : 1) << "plate node " << n;
}

// Uneven element ranges (the chunk plan's, solver/chunk_plan): with every element chunk on thread 0,
// every plate node is thread 0's; the body's nodes still go to the threads that place them. Back to
// even ranges, plate 2 is thread 1's again (the table follows its bounds).
TEST(NodeChunkOwners, NodesFollowUnevenElementRanges) {
  const model::Model model = body_and_two_plates();
  const long body_nodes = long(model.rigid_bodies[0].nodes.size());
  const long chunks = long(model.schedule.chunks.size());
  solver::NodeChunkOwners owners(model, 1);
  const std::vector<long> all_on_0{0, chunks, chunks};
  const auto owner_of = [&](const std::vector<std::vector<long>>& table) {
    std::vector<int> owner(model.num_nodes(), -1);
    for (int t = 0; t < 2; ++t)
      for (long c : table[std::size_t(t)]) owner[std::size_t(c)] = t;
    return owner;
  };
  std::vector<int> owner = owner_of(owners.for_bounds(all_on_0));
  for (std::size_t n = std::size_t(body_nodes); n < model.num_nodes(); ++n) EXPECT_EQ(owner[n], 0) << "plate node " << n;
  const auto& nodes = model.rigid_bodies[0].nodes;
  for (long k = 0; k < body_nodes; ++k)
    EXPECT_EQ(owner[std::size_t(nodes[std::size_t(k)])], k < body_nodes / 2 ? 0 : 1) << "body node " << k;
  owner = owner_of(owners.for_threads(2));
  EXPECT_EQ(owner.back(), 1);
}

TEST(NodeChunkOwners, EveryChunkOnceInIncreasingOrderForAnyThreadCount) {
  const model::Model model = body_and_two_plates();
  solver::NodeChunkOwners owners(model, 1024);
  const long chunks = long((model.num_nodes() + 1023) / 1024);
  for (int nt : {1, 2, 3, 2}) {  // back to 2: the kept table
    const auto& table = owners.for_threads(nt);
    ASSERT_EQ(int(table.size()), nt);
    std::set<long> seen;
    for (const auto& mine : table) {
      EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
      for (long c : mine) EXPECT_TRUE(seen.insert(c).second) << "chunk " << c << " twice, " << nt << " threads";
    }
    EXPECT_EQ(long(seen.size()), chunks) << nt << " threads";
    if (nt == 1) {
      EXPECT_EQ(long(table[0].size()), chunks);
    }
  }
}

}  // namespace
}  // namespace plyimpact
