// Meshes in (mesh: {file: ...}): a laminate meshed by the gmsh layup mesher, written as .msh the way
// `plyimpact mesh` writes it, read back and run, must be the same model as the laminate meshed
// directly: identical coordinates (the writer stores binary doubles), elements in the same order
// with the same parts, the same delaminating interfaces and support node set. The run is then the
// same computation, so history.csv is compared byte for byte (the solver is deterministic for a
// given model). A hand-written ASCII MSH 4.1 file checks the ASCII path, physical groups as parts
// (by name) and node sets, and the refusals (other element types, unknown part, missing group).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "config/scene_loader.hpp"
#include "interop_support.hpp"
#include "mesh/scene_mesher.hpp"

using namespace plyimpact;
namespace fs = std::filesystem;

namespace {

const std::string kCommon = R"(units: mm-t-s-MPa
control: {termination_time: 3.0e-5}
output: {interval: 1.5e-5, history_interval: 1.0e-6}
materials:
  ply: {card: MAT_002, RO: 1.55e-9, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.019, PRCA: 0.019,
        PRCB: 0.53, GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}
sections:
  s: {ELFORM: 1, IHQ: 4}
)";

const std::string kImpactor = R"(impactor: {shape: sphere, diameter: 6, mass: 0.01 kg, gap: 0.02, velocity: 5 m/s,
           element_size: 1.5, position: [10, 10]}
contacts:
  - {name: tup, type: automatic_surface_to_surface, surfaces: [impactor, [ply_1_0, ply_2_90, ply_3_90, ply_4_0]]}
)";

std::string direct_scene() {
  return kCommon + R"(laminate: {length: 20, width: 20, ply_thickness: 0.25, stacking: "[0/90]s", material: ply, section: s,
           element_size: 2.5, interfaces: angle-change, supports: {window: {window: [15, 15]}}}
)" + kImpactor;
}

std::string file_scene(const std::string& msh) {
  return kCommon + R"(parts:
  ply_1_0: {material: ply, section: s, beta: 0}
  ply_2_90: {material: ply, section: s, beta: 90}
  ply_3_90: {material: ply, section: s, beta: 90}
  ply_4_0: {material: ply, section: s, beta: 0}
mesh: {file: )" + msh + R"(, length_unit: m}
node_sets:
  window: from_mesh
boundary_conditions:
  - {node_set: window, fix: [z]}
)" + kImpactor;
}

std::set<std::pair<Index, Index>> pairs(const mesh::Interface& i) {
  std::set<std::pair<Index, Index>> out;
  for (std::size_t k = 0; k < i.lower_nodes.size(); ++k) out.insert({i.lower_nodes[k], i.upper_nodes[k]});
  return out;
}

TEST(MshReader, LaminateWrittenByMeshCommandReadsBackAndRunsIdentically) {
  const fs::path dir = test::scratch_dir();
  const config::Scene direct = config::load_scene_from_string(direct_scene(), (dir / "direct.yaml").string());
  const mesh::Mesh a = mesh::mesh_scene(direct);
  mesh::write_msh(direct, a, (dir / "plate.msh").string());
  // The file path is relative to the scene file's folder.
  const config::Scene from_file = config::load_scene_from_string(file_scene("plate.msh"), (dir / "file.yaml").string());
  const mesh::Mesh b = mesh::mesh_scene(from_file);

  ASSERT_EQ(a.coords.size(), b.coords.size());
  EXPECT_TRUE(a.coords == b.coords) << "coordinates differ";
  EXPECT_TRUE(a.hex == b.hex) << "connectivity differs";
  EXPECT_TRUE(a.element_part == b.element_part);
  ASSERT_EQ(a.interfaces.size(), 2u);
  ASSERT_EQ(a.interfaces.size(), b.interfaces.size());
  for (std::size_t i = 0; i < a.interfaces.size(); ++i) {
    EXPECT_EQ(a.interfaces[i].id, b.interfaces[i].id);
    EXPECT_EQ(a.interfaces[i].z, b.interfaces[i].z);
    EXPECT_TRUE(a.interfaces[i].lower_segments == b.interfaces[i].lower_segments);
    EXPECT_TRUE(a.interfaces[i].upper_segments == b.interfaces[i].upper_segments);
    // Pairs come back in segment order rather than the mesher's: the same set.
    EXPECT_TRUE(pairs(a.interfaces[i]) == pairs(b.interfaces[i]));
  }
  const auto window = [](const mesh::Mesh& m) {
    for (const auto& s : m.node_sets)
      if (s.name == "window") return std::set<Index>(s.nodes.begin(), s.nodes.end());
    return std::set<Index>{};
  };
  EXPECT_FALSE(window(a).empty());
  EXPECT_TRUE(window(a) == window(b));
  ASSERT_TRUE(a.impactor && b.impactor);
  EXPECT_TRUE(a.impactor->surface_coords == b.impactor->surface_coords);

  const std::string h1 = test::run_history(direct, dir / "run_direct");
  const std::string h2 = test::run_history(from_file, dir / "run_file");
  EXPECT_GT(std::count(h1.begin(), h1.end(), '\n'), 25);
  EXPECT_EQ(h1, h2);
  fs::remove_all(dir);
}

// Two unit cubes stacked in z (12 nodes), ASCII MSH 4.1: volume "block" holds both hexahedra,
// surface "bottom" (a quadrangle) and point "corner" are node sets.
std::string two_hex_msh(const std::string& extra_element_block = "") {
  std::string nodes;
  int tag = 1;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) nodes += std::to_string(tag++) + "\n";
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) nodes += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  const int blocks = extra_element_block.empty() ? 3 : 4;
  const int count = extra_element_block.empty() ? 4 : 5;
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
         "$PhysicalNames\n3\n0 3 \"corner\"\n2 2 \"bottom\"\n3 1 \"block\"\n$EndPhysicalNames\n"
         "$Entities\n1 0 1 1\n1 0 0 0 1 3\n1 0 0 0 1 1 0 1 2 0\n1 0 0 0 1 1 2 1 1 0\n$EndEntities\n"
         "$Nodes\n1 12 1 12\n3 1 0 12\n" + nodes + "$EndNodes\n"
         "$Elements\n" + std::to_string(blocks) + " " + std::to_string(count) + " 1 " + std::to_string(count) + "\n"
         "3 1 5 2\n1 1 2 4 3 5 6 8 7\n2 5 6 8 7 9 10 12 11\n"
         "2 1 3 1\n3 1 3 4 2\n"
         "0 1 15 1\n4 1\n" + extra_element_block + "$EndElements\n";
}

std::string box_scene(const std::string& node_set = "corner") {
  return "units: SI\ncontrol: {termination_time: 1e-6}\n"
         "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
         "sections:\n  s: {}\n"
         "parts:\n  block: {material: steel, section: s}\n"
         "mesh: {file: two.msh}\n"
         "node_sets:\n  " + node_set + ": from_mesh\n  bottom: from_mesh\n";
}

TEST(MshReader, AsciiFileGivesPartsAndNodeSetsInTheScenesLengthUnit) {
  const fs::path dir = test::scratch_dir();
  test::write_file(dir / "two.msh", two_hex_msh());
  const auto scene = config::load_scene_from_string(box_scene(), (dir / "s.yaml").string());
  const mesh::Mesh m = mesh::mesh_scene(scene);
  ASSERT_EQ(m.num_nodes(), 12u);
  ASSERT_EQ(m.num_elements(), 2u);
  EXPECT_EQ(m.coords[3 * 11 + 2], 2.0);  // node 12 at z = 2 (SI scene, no length_unit: metres)
  EXPECT_EQ(m.hex[8], 4);                // element 2 starts at node 5 (0-based 4)
  std::set<std::string> names;
  for (const auto& s : m.node_sets) names.insert(s.name);
  EXPECT_TRUE(names.count("bottom") && names.count("corner") && names.count("block"));
  for (const auto& s : m.node_sets)
    if (s.name == "bottom") {
      EXPECT_EQ(s.nodes, (std::vector<Index>{0, 1, 2, 3}));
    }
  fs::remove_all(dir);
}

std::string error_of(const std::string& scene_text, const fs::path& dir) {
  try {
    const auto scene = config::load_scene_from_string(scene_text, (dir / "s.yaml").string());
    mesh::mesh_scene(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MshReader, RefusesOtherVolumeElementsWithFileTypeAndCount) {
  const fs::path dir = test::scratch_dir();
  // One 4-node tetrahedron (gmsh type 4) in the same volume.
  test::write_file(dir / "two.msh", two_hex_msh("3 1 4 1\n5 1 2 3 5\n"));
  const std::string e = error_of(box_scene(), dir);
  EXPECT_NE(e.find("two.msh"), std::string::npos) << e;
  EXPECT_NE(e.find("1 elements of type 'Tetrahedron 4' (gmsh type 4)"), std::string::npos) << e;
  EXPECT_NE(e.find("allowed: 8-node hexahedra only"), std::string::npos) << e;
  fs::remove_all(dir);
}

TEST(MshReader, RefusesUnknownPartAndMissingGroupNamingThem) {
  const fs::path dir = test::scratch_dir();
  test::write_file(dir / "two.msh", two_hex_msh());
  std::string renamed = box_scene();
  renamed.replace(renamed.find("  block:"), 8, "  plate:");
  const std::string e1 = error_of(renamed, dir);
  EXPECT_NE(e1.find("physical volume 1 'block' matches no part"), std::string::npos) << e1;
  EXPECT_NE(e1.find("'plate' (id 1)"), std::string::npos) << e1;
  const std::string e2 = error_of(box_scene("top"), dir);
  EXPECT_NE(e2.find("s.yaml:"), std::string::npos) << e2;
  EXPECT_NE(e2.find("has no physical group 'top'"), std::string::npos) << e2;
  fs::remove_all(dir);
}

}  // namespace
