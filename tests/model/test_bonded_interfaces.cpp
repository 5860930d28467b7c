// Bonded interfaces: a laminate meshed with delaminating interfaces (duplicated, coincident nodes
// at every angle change) is built bonded by the model builder, which points the upper ply's
// elements at the lower partner nodes. The result must be the laminate meshed without interfaces:
// the same nodes in use (coordinates), the same elements over them, the same lumped masses (the
// left-over duplicates massless), and the same response when only the top ply is set moving: the
// load has to cross every interface. Independent reference: the same laminate meshed with
// `interfaces: none`. Tolerances: coordinates and masses to round-off (1e-12 relative); the response
// to 1e-9 of the largest velocity (same elements in the same order, but node numbers differ, and so
// may the order in which element forces are summed at a node).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "../mesher/scene_cards.hpp"
#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

model::Model laminate(const std::string& interfaces) {
  const config::Scene scene = config::load_scene_from_string(
      "units: mm-t-s-MPa\ncontrol: {termination_time: 1.0e-5}\n" + std::string(test::kPlyCards) +
          "laminate:\n  length: 8\n  width: 6\n  ply_thickness: 0.25\n  stacking: \"[0/90]s\"\n  material: ply\n"
          "  section: s\n  element_size: 1\n  interfaces: " + interfaces + "\n"
          "initial_velocity:\n  - {part: ply_4_0, velocity: [0, 0, \"-1 m/s\"]}\n",
      "bonded.yaml");
  return model::build_model(scene, mesh::mesh_scene(scene));
}

using Key = std::array<long, 3>;  // coordinates on a 1e-9 m grid (the mesh is on a 0.25 mm grid)
Key key_of(const model::Model& m, Index n) {
  return {std::lround(m.X[3 * n] * 1e9), std::lround(m.X[3 * n + 1] * 1e9), std::lround(m.X[3 * n + 2] * 1e9)};
}

// Used nodes (in some element) by position.
std::map<Key, Index> used_nodes(const model::Model& m) {
  std::map<Key, Index> nodes;
  for (const auto& b : m.blocks)
    for (Index n : b.conn) {
      const auto [it, fresh] = nodes.emplace(key_of(m, n), n);
      EXPECT_TRUE(fresh || it->second == n) << "two used nodes at one position: an interface left open";
    }
  return nodes;
}

TEST(BondedInterfaces, MergedLaminateIsTheLaminateMeshedWithoutInterfaces) {
  const model::Model bonded = laminate("angle-change"), plain = laminate("none");
  ASSERT_EQ(bonded.interfaces.size(), 2u);  // 0/90 and 90/0 (the 90/90 middle is not an angle change)
  EXPECT_TRUE(bonded.interfaces_bonded);
  ASSERT_TRUE(plain.interfaces.empty());
  const auto nb = used_nodes(bonded), np = used_nodes(plain);
  ASSERT_EQ(nb.size(), np.size());
  ASSERT_GT(bonded.num_nodes(), nb.size());  // the duplicates are still there, unused
  for (const auto& [k, n] : np) {
    const auto it = nb.find(k);
    ASSERT_NE(it, nb.end()) << "node of the plain laminate missing in the bonded one";
    EXPECT_NEAR(bonded.mass[it->second], plain.mass[n], 1e-12 * plain.mass[n]);
  }
  for (std::size_t n = 0; n < bonded.num_nodes(); ++n)
    if (nb.find(key_of(bonded, Index(n))) == nb.end() || nb.at(key_of(bonded, Index(n))) != Index(n)) {
      EXPECT_EQ(bonded.mass[n], 0.0) << "an unused duplicate carries mass";
    }
  // Same elements, in the same order, over the same positions.
  ASSERT_EQ(bonded.blocks.size(), plain.blocks.size());
  for (std::size_t b = 0; b < plain.blocks.size(); ++b) {
    ASSERT_EQ(bonded.blocks[b].conn.size(), plain.blocks[b].conn.size());
    for (std::size_t k = 0; k < plain.blocks[b].conn.size(); ++k)
      ASSERT_EQ(key_of(bonded, bonded.blocks[b].conn[k]), key_of(plain, plain.blocks[b].conn[k]))
          << "block " << b << ", element node " << k;
  }

  // Response: only the top ply starts moving; after 2 us (the through-thickness wave has crossed
  // the 1 mm several times) every node must move as in the plain laminate.
  solver::Solver sb(bonded), sp(plain);
  while (sp.state().time < 2e-6) {
    sb.step();
    sp.step();
  }
  double vmax = 0, worst = 0, bottom = 0;
  for (const auto& [k, n] : np) {
    const Index m = nb.at(k);
    for (int d = 0; d < 3; ++d) {
      vmax = std::max(vmax, std::abs(sp.state().v[3 * n + d]));
      worst = std::max(worst, std::abs(sb.state().v[3 * m + d] - sp.state().v[3 * n + d]));
    }
    if (k[2] == 0) bottom = std::max(bottom, std::abs(sb.state().v[3 * m + 2]));
  }
  std::cout << "bonded laminate: " << nb.size() << " nodes in use of " << bonded.num_nodes() << ", largest velocity "
            << vmax << " m/s, largest difference " << worst << " m/s, bottom face " << bottom << " m/s\n";
  EXPECT_LT(worst, 1e-9 * vmax);
  EXPECT_GT(bottom, 0.1 * vmax) << "the bottom ply did not take up the top ply's motion";
}

}  // namespace
}  // namespace plyimpact
