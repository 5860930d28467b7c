// The gmsh laminate mesher: counts derived by hand, exact volume, positive corner Jacobians, node
// order, interface pairs and segments, shared nodes elsewhere, generated node sets, nested
// refinement levels, and the loader's refusals (symmetry of the layup, bad notation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "scene_cards.hpp"
#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "element/hex8.hpp"
#include "mesh/laminate_mesher.hpp"
#include "mesh/scene_mesher.hpp"

using namespace plyimpact;

namespace {

// A laminate scene in mm; `laminate` is the body of the laminate section (indented by 2).
std::string scene_text(const std::string& laminate) {
  return R"(units: mm-t-s-MPa
control: {termination_time: 1.0e-6}
)" + std::string(test::kPlyCards) + R"(laminate:
  material: ply
  section: s
)" + laminate;
}

config::Scene load(const std::string& laminate) { return config::load_scene_from_string(scene_text(laminate), "t.yaml"); }

void gather(const mesh::Mesh& m, std::size_t e, double x[3][8]) {
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) x[i][k] = m.coords[3 * std::size_t(m.hex[8 * e + k]) + i];
}

// 20 x 10 mm, 4 plies of 0.25 mm, 2 elements per ply, 2 mm: 10 x 5 x 8 elements.
const char* kSmall = R"(  length: 20
  width: 10
  ply_thickness: 0.25
  stacking: "[0/90]s"
  elements_per_ply: 2
  element_size: 2
)";

}  // namespace

TEST(LaminateMesher, CountsVolumeJacobiansAndNodeOrder) {
  const config::Scene scene = load(std::string(kSmall) + "  interfaces: none\n");
  const mesh::Mesh m = mesh::mesh_laminate(scene);
  EXPECT_EQ(m.num_elements(), 10u * 5 * 8);
  EXPECT_EQ(m.num_nodes(), 11u * 6 * 9);  // no delamination: nothing duplicated
  EXPECT_TRUE(m.interfaces.empty());
  double volume = 0;
  for (std::size_t e = 0; e < m.num_elements(); ++e) {
    double x[3][8], detj[8];
    gather(m, e, x);
    element::hex8_corner_jacobians(x, detj);
    for (int k = 0; k < 8; ++k) ASSERT_GT(detj[k], 0.0) << "element " << e << " corner " << k;
    volume += element::hex8_volume(x);
    // LS-DYNA / VTK_HEXAHEDRON order: 0-3 counter-clockwise on the bottom seen from +z, 4-7 above.
    EXPECT_LT(x[0][0], x[0][1]);
    EXPECT_EQ(x[1][1], x[1][0]);
    EXPECT_LT(x[1][1], x[1][2]);
    EXPECT_EQ(x[0][3], x[0][0]);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(x[0][k + 4], x[0][k]);
      EXPECT_EQ(x[1][k + 4], x[1][k]);
      EXPECT_GT(x[2][k + 4], x[2][k]);
    }
    const int ply = m.element_ply[e];
    EXPECT_GE(x[2][0], 0.25e-3 * ply - 1e-15);
    EXPECT_LE(x[2][4], 0.25e-3 * (ply + 1) + 1e-15);
  }
  EXPECT_NEAR(volume, 20e-3 * 10e-3 * 1e-3, 1e-12 * 20e-3 * 10e-3 * 1e-3);
  // One part per ply, in stacking order, with the ply angle as beta.
  ASSERT_EQ(scene.parts.size(), 4u);
  EXPECT_EQ(scene.parts[1].name, "ply_2_90");
  EXPECT_DOUBLE_EQ(scene.parts[1].beta, M_PI / 2);
}

TEST(LaminateMesher, DelaminatingInterfacesHaveCoincidentOneToOnePairs) {
  // [0/90]s: angle changes at interfaces 1 and 3; interface 2 (90/90) shares its nodes.
  const config::Scene scene = load(std::string(kSmall) + "  interfaces: angle-change\n");
  const mesh::Mesh m = mesh::mesh_laminate(scene);
  ASSERT_EQ(m.interfaces.size(), 2u);
  EXPECT_EQ(m.num_nodes(), 11u * 6 * 9 + 2 * 11 * 6);
  const double z_of[2] = {0.25e-3, 0.75e-3};
  for (int n = 0; n < 2; ++n) {
    const auto& itf = m.interfaces[std::size_t(n)];
    EXPECT_EQ(itf.id, n == 0 ? 1 : 3);
    EXPECT_EQ(itf.upper_ply, itf.lower_ply + 1);
    ASSERT_EQ(itf.lower_nodes.size(), 66u);
    ASSERT_EQ(itf.upper_nodes.size(), 66u);
    EXPECT_EQ(itf.lower_segments.size(), 4u * 50);
    EXPECT_EQ(itf.upper_segments.size(), 4u * 50);
    std::set<Index> lower(itf.lower_nodes.begin(), itf.lower_nodes.end()),
        upper(itf.upper_nodes.begin(), itf.upper_nodes.end());
    EXPECT_EQ(lower.size(), 66u);  // one-to-one
    EXPECT_EQ(upper.size(), 66u);
    for (std::size_t k = 0; k < 66; ++k) {
      const double* a = &m.coords[3 * std::size_t(itf.lower_nodes[k])];
      const double* b = &m.coords[3 * std::size_t(itf.upper_nodes[k])];
      EXPECT_NE(itf.lower_nodes[k], itf.upper_nodes[k]);
      for (int d = 0; d < 3; ++d) EXPECT_EQ(a[d], b[d]);  // exactly coincident
      EXPECT_NEAR(a[2], z_of[n], 1e-18);                   // on the ply boundary
      EXPECT_FALSE(upper.count(itf.lower_nodes[k]));
    }
    // Lower nodes are used only by the lower ply (and below), upper nodes only by the upper ply.
    for (std::size_t e = 0; e < m.num_elements(); ++e)
      for (int k = 0; k < 8; ++k) {
        const auto node = m.hex[8 * e + k];
        if (lower.count(node)) {
          EXPECT_EQ(m.element_ply[e], itf.lower_ply);
        }
        if (upper.count(node)) {
          EXPECT_EQ(m.element_ply[e], itf.upper_ply);
        }
      }
    // Segment k on both sides is the same face: same corner set of coordinates, opposite normals.
    for (std::size_t s = 0; s < 50; ++s) {
      const auto* lo = &itf.lower_segments[4 * s];
      const auto* up = &itf.upper_segments[4 * s];
      const int order[4] = {0, 3, 2, 1};
      for (int k = 0; k < 4; ++k)
        for (int d = 0; d < 3; ++d)
          EXPECT_EQ(m.coords[3 * std::size_t(lo[k]) + d], m.coords[3 * std::size_t(up[order[k]]) + d]);
    }
  }
  // Untagged interface 2 (z = 0.5 mm): its nodes are shared by plies 2 and 3.
  std::map<Index, std::set<int>> plies_at;
  for (std::size_t e = 0; e < m.num_elements(); ++e)
    for (int k = 0; k < 8; ++k) {
      const auto node = m.hex[8 * e + k];
      if (std::abs(m.coords[3 * std::size_t(node) + 2] - 0.5e-3) < 1e-12) plies_at[node].insert(m.element_ply[e]);
    }
  EXPECT_EQ(plies_at.size(), 66u);
  for (const auto& [node, plies] : plies_at) EXPECT_EQ(plies, (std::set<int>{1, 2})) << node;
}

TEST(LaminateMesher, WindowSupportAndSymmetryPlanes) {
  // Quarter of a 40 x 20 mm plate on a 30 x 10 mm window: modelled 20 x 10 mm, 1 mm elements.
  const config::Scene scene = load(R"(  length: 40
  width: 20
  ply_thickness: 0.5
  stacking: [0, 90]
  element_size: 1
  symmetry: [x, y]
  supports:
    win: {window: [30, 10]}
)");
  const mesh::Mesh m = mesh::mesh_laminate(scene);
  EXPECT_EQ(m.num_elements(), 20u * 10 * 2);
  std::map<std::string, std::vector<Index>> sets;
  for (const auto& s : m.node_sets) sets[s.name] = s.nodes;
  // Window outline in the quarter: x = 5 mm for y in [5, 10] (6 nodes), y = 5 mm for x in [5, 20]
  // (16 nodes), sharing (5, 5): 21 nodes, all on the bottom face.
  ASSERT_EQ(sets["win"].size(), 21u);
  for (auto n : sets["win"]) EXPECT_EQ(m.coords[3 * std::size_t(n) + 2], 0.0);
  EXPECT_EQ(sets["symmetry_x"].size(), 11u * 3);  // x = 20 mm: 11 x 3 nodes
  EXPECT_EQ(sets["symmetry_y"].size(), 21u * 3);
  // Fixed conditions generated: window z, symmetry x / y.
  ASSERT_EQ(scene.boundary_conditions.size(), 3u);
  EXPECT_EQ(scene.boundary_conditions[0].dofs, (std::array<bool, 3>{false, false, true}));
  EXPECT_EQ(scene.boundary_conditions[1].dofs, (std::array<bool, 3>{true, false, false}));
}

TEST(LaminateMesher, RefinementLevelsNest) {
  auto text = [](int level) {
    return std::string(R"(  length: 40
  width: 30
  ply_thickness: 0.5
  stacking: "[0/90]"
  element_size: 4
  refined_zone: {size: [10, 6], element_size: 1}
  refinement_level: )") + std::to_string(level) + "\n";
  };
  std::vector<mesh::Mesh> meshes;
  for (int level : {0, 1, 2}) meshes.push_back(mesh::mesh_laminate(load(text(level))));
  const std::size_t ne = meshes[0].num_elements();
  EXPECT_EQ(meshes[1].num_elements(), 4 * ne);  // in-plane halving, same layers through the thickness
  EXPECT_EQ(meshes[2].num_elements(), 16 * ne);
  for (int fine = 1; fine <= 2; ++fine) {
    std::set<std::array<double, 3>> nodes;
    for (std::size_t a = 0; a < meshes[std::size_t(fine)].num_nodes(); ++a) {
      const double* p = &meshes[std::size_t(fine)].coords[3 * a];
      nodes.insert({p[0], p[1], p[2]});
    }
    for (std::size_t a = 0; a < meshes[0].num_nodes(); ++a) {
      const double* p = &meshes[0].coords[3 * a];
      EXPECT_TRUE(nodes.count({p[0], p[1], p[2]})) << "coarse node " << a << " missing at level " << fine;
    }
  }
}

TEST(LaminateMesher, LoaderRefusesAsymmetricLayupAndBadNotation) {
  try {
    load(std::string(kSmall).replace(std::string(kSmall).find("[0/90]s"), 7, "[0/45]s") + "  symmetry: [x]\n");
    FAIL() << "accepted a symmetry plane for a 45 degree ply";
  } catch (const InputError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("t.yaml:"), std::string::npos) << w;
    EXPECT_NE(w.find("laminate.symmetry"), std::string::npos) << w;
    EXPECT_NE(w.find("not symmetric about this plane"), std::string::npos) << w;
  }
  try {
    load(std::string(kSmall).replace(std::string(kSmall).find("[0/90]s"), 7, "[0/90]q"));
    FAIL() << "accepted bad notation";
  } catch (const InputError& e) {
    const std::string w = e.what();
    // Line 14 of the scene; the quote is at column 13, the 'q' is character 7 of the notation.
    EXPECT_NE(w.find("t.yaml:14:20: laminate.stacking: bad laminate notation: unexpected 'q'"), std::string::npos) << w;
    EXPECT_NE(w.find("; allowed laminate notation such as"), std::string::npos) << w;
  }
}

TEST(LaminateMesher, GroupedPliesShareAPart) {
  const config::Scene scene = load(R"(  length: 4
  width: 4
  ply_thickness: 0.25
  stacking: "[0_2/90]s"
  element_size: 2
  group_plies: true
  interfaces: angle-change
)");
  ASSERT_EQ(scene.parts.size(), 3u);  // 0/0 | 90/90 | 0/0
  EXPECT_EQ(scene.parts[0].name, "plies_1-2_0");
  EXPECT_EQ(scene.parts[1].name, "plies_3-4_90");
  const mesh::Mesh m = mesh::mesh_laminate(scene);
  EXPECT_EQ(m.interfaces.size(), 2u);
  EXPECT_EQ(m.element_ply.size(), 2u * 2 * 6);
  EXPECT_EQ(m.element_part[0], 0);
  EXPECT_EQ(m.element_ply[4], 1);  // second ply of the first block
}

// laminate.impact_zone: the elements whose centre lies in the zone get a part per ply of their own
// with the zone's section (same material and ply angle); a contact naming a ply takes its zone part
// along. The zone is the refined zone here, so its edges are grid lines and each ply has exactly
// 10 x 6 zone elements of 1 mm; the refusals name the key.
TEST(LaminateMesher, ImpactZoneElementsFormPartsOfTheirOwn) {
  const std::string cards = std::string(test::kPlyCards) + "  full: {ELFORM: -2}\n";
  auto scene_with = [&](const std::string& zone) {
    return "units: mm-t-s-MPa\ncontrol: {termination_time: 1.0e-6}\n" + cards + R"(laminate:
  material: ply
  section: s
  length: 40
  width: 30
  ply_thickness: 0.5
  stacking: "[0/90]"
  element_size: 4
  refined_zone: {size: [10, 6], element_size: 1}
)" + zone + R"(contacts:
  - {name: plies, type: automatic_single_surface, parts: [ply_1_0, ply_2_90]}
)";
  };
  const config::Scene scene =
      config::load_scene_from_string(scene_with("  impact_zone: {size: [10, 6], section: full}\n"), "t.yaml");
  ASSERT_EQ(scene.parts.size(), 4u);
  const char* names[4] = {"ply_1_0", "ply_1_0_zone", "ply_2_90", "ply_2_90_zone"};
  for (int p = 0; p < 4; ++p) {
    EXPECT_EQ(scene.parts[std::size_t(p)].name, names[p]);
    EXPECT_EQ(scene.parts[std::size_t(p)].section, p % 2 ? "full" : "s");
    EXPECT_EQ(scene.parts[std::size_t(p)].material, "ply");
    EXPECT_EQ(scene.parts[std::size_t(p)].beta, scene.parts[std::size_t(p - p % 2)].beta);
  }
  ASSERT_EQ(scene.contacts.size(), 1u);
  EXPECT_EQ(scene.contacts[0].surface_a,
            (std::vector<std::string>{"ply_1_0", "ply_2_90", "ply_1_0_zone", "ply_2_90_zone"}));

  const mesh::Mesh m = mesh::mesh_laminate(scene);
  const double cx = 0.020, cy = 0.015;  // impact point: the plate centre, m
  std::size_t zone_elements[2] = {0, 0};
  double zone_volume[2] = {0, 0};
  for (std::size_t e = 0; e < m.num_elements(); ++e) {
    double x[3][8], detj[8], centre[2] = {0, 0};
    gather(m, e, x);
    for (int k = 0; k < 8; ++k) centre[0] += x[0][k] / 8, centre[1] += x[1][k] / 8;
    const bool inside = std::abs(centre[0] - cx) < 0.005 && std::abs(centre[1] - cy) < 0.003;
    const int ply = m.element_ply[e];
    EXPECT_EQ(m.element_part[e], 2 * ply + (inside ? 1 : 0)) << "element " << e;
    if (m.element_part[e] != 2 * ply + 1) continue;
    ++zone_elements[ply];
    element::hex8_corner_jacobians(x, detj);
    for (double d : detj) zone_volume[ply] += d;  // corner rule: exact for a box
  }
  for (int ply = 0; ply < 2; ++ply) {
    EXPECT_EQ(zone_elements[ply], 60u);
    EXPECT_NEAR(zone_volume[ply], 10e-3 * 6e-3 * 0.5e-3, 1e-15);
  }

  auto refusal = [&](const std::string& zone, bool at_meshing) {
    try {
      const config::Scene bad = config::load_scene_from_string(scene_with(zone), "t.yaml");
      if (at_meshing) mesh::mesh_laminate(bad);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string w = refusal("  impact_zone: {size: [10, 6], section: ful}\n", false);
  EXPECT_NE(w.find("t.yaml:18:"), std::string::npos) << w;
  EXPECT_NE(w.find("laminate.impact_zone.section"), std::string::npos) << w;
  EXPECT_NE(w.find("full"), std::string::npos) << w;
  w = refusal("  impact_zone: {size: [40, 6], section: full}\n", false);
  EXPECT_NE(w.find("the impact zone reaches the plate edge"), std::string::npos) << w;
  w = refusal("  impact_zone: {size: [0.5, 0.5], section: full}\n", true);  // centres lie 0.5 mm off the point
  EXPECT_NE(w.find("t.yaml:18:"), std::string::npos) << w;
  EXPECT_NE(w.find("laminate.impact_zone: no element centre lies in the 0.5 x 0.5 mm impact zone"), std::string::npos) << w;
}

// mesh_scene renumbers a laminate's nodes in the order its plies' elements first use them
// (mesh/node_order): the mesh must be the same mesh (every element's corners, every interface
// pair and segment, every node set at the same coordinates), and the nodes each ply brings must be
// one range following the previous ply's.
TEST(NodeOrder, RenumberedLaminateIsTheSameMeshWithEachPlysNodesContiguous) {
  const config::Scene scene = load(R"(  length: 20
  width: 10
  ply_thickness: 0.25
  stacking: "[0/90]s"
  element_size: 2
  interfaces: angle-change
  supports:
    win: {window: [16, 6]}
)");
  const mesh::Mesh before = mesh::mesh_laminate(scene);
  const mesh::Mesh after = mesh::mesh_scene(scene);
  ASSERT_EQ(after.num_nodes(), before.num_nodes());
  ASSERT_EQ(after.hex.size(), before.hex.size());
  ASSERT_FALSE(before.interfaces.empty());
  auto same_point = [&](Index a, Index b) {
    for (int i = 0; i < 3; ++i)
      if (before.coords[3 * std::size_t(a) + i] != after.coords[3 * std::size_t(b) + i]) return false;
    return true;
  };
  auto same_points = [&](const std::vector<Index>& a, const std::vector<Index>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (!same_point(a[k], b[k])) return false;
    return true;
  };
  EXPECT_TRUE(same_points(before.hex, after.hex));
  ASSERT_EQ(after.interfaces.size(), before.interfaces.size());
  for (std::size_t i = 0; i < before.interfaces.size(); ++i) {
    EXPECT_TRUE(same_points(before.interfaces[i].lower_nodes, after.interfaces[i].lower_nodes));
    EXPECT_TRUE(same_points(before.interfaces[i].upper_nodes, after.interfaces[i].upper_nodes));
    EXPECT_TRUE(same_points(before.interfaces[i].lower_segments, after.interfaces[i].lower_segments));
    EXPECT_TRUE(same_points(before.interfaces[i].upper_segments, after.interfaces[i].upper_segments));
  }
  ASSERT_EQ(after.node_sets.size(), before.node_sets.size());
  for (std::size_t s = 0; s < before.node_sets.size(); ++s)
    EXPECT_TRUE(same_points(before.node_sets[s].nodes, after.node_sets[s].nodes)) << before.node_sets[s].name;
  // A permutation: every new index used once.
  std::set<Index> used(after.hex.begin(), after.hex.end());
  EXPECT_EQ(used.size(), after.num_nodes());
  // Part by part, the nodes a part uses first are exactly the next range of indices.
  Index next = 0;
  std::set<Index> seen;
  const int parts = *std::max_element(after.element_part.begin(), after.element_part.end()) + 1;
  for (int p = 0; p < parts; ++p) {
    std::set<Index> brought;
    for (std::size_t e = 0; e < after.num_elements(); ++e)
      if (after.element_part[e] == p)
        for (int k = 0; k < 8; ++k)
          if (!seen.count(after.hex[8 * e + k])) brought.insert(after.hex[8 * e + k]);
    if (brought.empty()) continue;
    EXPECT_EQ(*brought.begin(), next) << "part " << p;
    EXPECT_EQ(*brought.rbegin(), next + Index(brought.size()) - 1) << "part " << p;
    next += Index(brought.size());
    seen.insert(brought.begin(), brought.end());
  }
  EXPECT_EQ(std::size_t(next), after.num_nodes());
}
