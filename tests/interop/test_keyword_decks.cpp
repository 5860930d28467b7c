// Keyword decks in. The decks under tests/data/decks are converted (scene YAML + .msh) and run; the
// same set-ups written directly as YAML scenes (box generator, the converter's names) must give the
// same history.csv byte for byte: the decks' meshes are in free (comma) format with every digit of
// the box generator's coordinates, node and element order are the generator's, and every value
// reaches the scene loader as the same number, so the two models are the same and the solver is
// deterministic. Parser tests: fixed, long and comma formats of the same cards read alike,
// *INCLUDE resolves against the including file, comments are skipped; refusals name file:line, the
// keyword and the field (unknown keyword, unsupported option, unsupported field value).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "deck_support.hpp"

using namespace plyimpact;
namespace fs = std::filesystem;

namespace {

using test::convert_text;
using test::deck_history;
using test::kDecks;
using test::refusal;
using test::yaml_history;

// tests/contact/test_rod_wall.cpp's set-up with default bulk viscosity and the converter's names.
TEST(KeywordDecks, RodOnRigidWallGivesTheHistoryOfTheYamlScene) {
  const fs::path dir = test::scratch_dir();
  const std::string yaml = R"(units: SI
control: {termination_time: 5.0e-5, tssfac: 0.9}
output: {interval: 2.5e-5, history_interval: 1.0e-6}
materials:
  mat_1: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}
sections:
  sec_1: {ELFORM: 2, IHQ: 2, QM: 0.1, Q1: 1.5, Q2: 0.06}
parts:
  part_1: {id: 1, material: mat_1, section: sec_1}
mesh:
  boxes:
    - {part: part_1, origin: [0, 0, 0.0001], size: [0.001, 0.001, 0.1], elements: [1, 1, 100]}
node_sets:
  set_1: all
boundary_conditions:
  - {node_set: set_1, fix: [x, y]}
initial_velocity:
  - {part: part_1, velocity: [0, 0, -10]}
rigid_walls:
  - {name: wall_1, point: [0, 0, 0], normal: [0, 0, 1]}
)";
  const std::string a = deck_history("rod_wall.k", dir), b = yaml_history(yaml, dir);
  EXPECT_GT(std::count(a.begin(), a.end(), '\n'), 45);  // 50 rows over 50 us: the rod hits and leaves the wall
  EXPECT_NE(a.find("wall_wall_1_normal"), std::string::npos);
  EXPECT_EQ(a, b);
  fs::remove_all(dir);
}

std::string mat054(const std::string& axes) {
  return "{card: MAT_054, RO: 1550, EA: 1.57e11, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895, PRCB: 0.53, "
         "GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, " + axes + ", DFAILM: 0.0105, DFAILS: 0, SOFT: 1, FBRT: 0, "
         "YCFAC: 2, DFAILT: 0.01557, DFAILC: -0.0105, XC: 1.2e9, XT: 2.2e9, YC: 2.8e8, YT: 4.5e7, SC: 4.5e7, "
         "CRIT: 54, BETA: 1}";
}

TEST(KeywordDecks, LaminateWithMat054GivesTheHistoryOfTheYamlScene) {
  const fs::path dir = test::scratch_dir();
  std::string yaml = R"(units: SI
control: {termination_time: 2.0e-5, tssfac: 0.9}
output: {interval: 1.0e-5, history_interval: 1.0e-7}
materials:
  mat_1: )" + mat054("A: [1, 0, 0], D: [0, 1, 0]") + R"(
  mat_2: )" + mat054("A: [0, 1, 0], D: [-1, 0, 0]") + R"(
sections:
  sec_1_hg1: {ELFORM: 1, IHQ: 6, QM: 1.0}
parts:
  part_1: {id: 1, material: mat_1, section: sec_1_hg1}
  part_2: {id: 2, material: mat_2, section: sec_1_hg1}
  part_3: {id: 3, material: mat_2, section: sec_1_hg1}
  part_4: {id: 4, material: mat_1, section: sec_1_hg1}
mesh:
  boxes:
    - {part: part_1, origin: [0, 0, 0], size: [0.01, 0.01, 0.00025], elements: [4, 4, 1]}
    - {part: part_2, origin: [0, 0, 0.00025], size: [0.01, 0.01, 0.00025], elements: [4, 4, 1]}
    - {part: part_3, origin: [0, 0, 0.0005], size: [0.01, 0.01, 0.00025], elements: [4, 4, 1]}
    - {part: part_4, origin: [0, 0, 0.00075], size: [0.01, 0.01, 0.00025], elements: [4, 4, 1]}
node_sets:
  set_1: {plane: {axis: x, value: 0}}
  set_2: {plane: {axis: x, value: 0.01}}
  set_3: {box: {min: [0.005, 0.005, 0.001], max: [0.005, 0.005, 0.001]}}
boundary_conditions:
  - {node_set: set_1, fix: [x, y, z]}
  - {node_set: set_2, fix: [x, y, z]}
  - {node_set: set_3, velocity: {dofs: [z], curve: [[0, 0], [1.0e-5, -5], [1, -5]]}}
)";
  const std::string a = deck_history("laminate_mat054.k", dir), b = yaml_history(yaml, dir);
  EXPECT_GT(std::count(a.begin(), a.end(), '\n'), 190);
  EXPECT_EQ(a, b);
  fs::remove_all(dir);
}

// Hertz-like impact: the sphere is meshed by the impactor mesher (gmsh) from the YAML scene, so
// the deck's mesh include is written here from that mesh (comma format, 17 significant digits:
// exact), numbered as the mesh is; the physics cards are the committed deck.
// A CSV text without the columns whose header starts with `prefix`.
std::string without_columns(const std::string& csv, const std::string& prefix) {
  std::istringstream in(csv);
  std::string line, out;
  std::vector<bool> keep;
  bool header = true;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string cell, row;
    for (std::size_t k = 0; std::getline(cells, cell, ','); ++k) {
      if (header) keep.push_back(cell.rfind(prefix, 0) != 0);
      if (k < keep.size() && keep[k]) row += (row.empty() ? "" : ",") + cell;
    }
    out += row + "\n";
    header = false;
  }
  return out;
}

TEST(KeywordDecks, SphereOnBlockGivesTheHistoryOfTheYamlScene) {
  const fs::path dir = test::scratch_dir();
  const std::string yaml = R"(units: SI
control: {termination_time: 2.0e-5, tssfac: 0.9}
output: {interval: 1.0e-5, history_interval: 2.0e-7}
materials:
  mat_1: {card: MAT_001, RO: 2700, E: 7.0e10, PR: 0.3}
  mat_2: {card: MAT_001, RO: 7850, E: 2.1e11, PR: 0.3}
sections:
  sec_1_hg1: {ELFORM: 1, IHQ: 3, QM: 0.1, Q1: 1.5, Q2: 0.06}
parts:
  part_1: {id: 1, material: mat_1, section: sec_1_hg1}
mesh:
  boxes:
    - {part: part_1, origin: [-0.005, -0.005, -0.005], size: [0.01, 0.01, 0.005], elements: [8, 8, 4]}
node_sets:
  set_1: {plane: {axis: z, value: -0.005}}
boundary_conditions:
  - {node_set: set_1, fix: [x, y, z]}
impactor: {shape: sphere, diameter: 0.006, rigid: false, material: mat_2, section: sec_1_hg1, gap: 5.0e-5,
           velocity: 5, element_size: 0.0015}
contacts:
  - {name: contact_1, type: automatic_surface_to_surface, surfaces: [impactor, part_1], SOFT: 0, SOFSCL: 0.1,
     MAXPAR: 1.025, FS: 0, FD: 0, SFS: 1, SFM: 1}
)";
  const config::Scene scene = config::load_scene_from_string(yaml, (dir / "yaml.yaml").string());
  const mesh::Mesh m = mesh::mesh_scene(scene);
  ASSERT_EQ(scene.parts.size(), 2u);
  std::string inc = "*NODE\n";
  char buf[160];
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    std::snprintf(buf, sizeof buf, "%zu,%.17g,%.17g,%.17g\n", i + 1, m.coords[3 * i], m.coords[3 * i + 1], m.coords[3 * i + 2]);
    inc += buf;
  }
  inc += "*ELEMENT_SOLID\n";
  for (std::size_t e = 0; e < m.num_elements(); ++e) {
    inc += std::to_string(e + 1);
    inc += ',';
    inc += std::to_string(scene.parts[std::size_t(m.element_part[e])].id);
    for (int k = 0; k < 8; ++k) {
      inc += ',';
      inc += std::to_string(m.hex[8 * e + k] + 1);
    }
    inc += "\n";
  }
  inc += "*SET_NODE_LIST\n1\n";
  for (std::size_t i = 0; i < m.num_nodes(); ++i)
    if (m.coords[3 * i + 2] == -0.005) {
      inc += std::to_string(i + 1);
      inc += '\n';
    }
  test::write_file(dir / "sphere_on_block_mesh.k", inc);
  fs::copy_file(kDecks / "sphere_on_block.k", dir / "sphere_on_block.k");
  keyword::convert_deck_file((dir / "sphere_on_block.k").string(), "SI", dir / "deck.yaml");
  const std::string a = test::run_history(config::load_scene((dir / "deck.yaml").string()), dir / "deck_run");
  // The YAML scene's `impactor:` section also records the deformable impactor's motion (impactor_*
  // columns, solver/impactor_motion.hpp); a deck's parts have no impactor role, so those columns
  // are left out of the comparison.
  const std::string b = without_columns(yaml_history(yaml, dir), "impactor_");
  EXPECT_GT(std::count(a.begin(), a.end(), '\n'), 95);
  // The sphere reaches the block (gap 50 um at 5 m/s: after 10 us) and pushes on it.
  std::istringstream rows(a);
  std::string header, row;
  std::getline(rows, header);
  const auto column = std::count(header.begin(), header.begin() + long(header.find("contact_contact_1_normal")), ',');
  double peak = 0;
  while (std::getline(rows, row)) {
    std::istringstream cells(row);
    std::string cell;
    for (long k = 0; k <= column; ++k) std::getline(cells, cell, ',');
    peak = std::max(peak, std::abs(std::stod(cell)));
  }
  std::cout << "sphere on block: peak contact force " << peak << " N\n";
  EXPECT_GT(peak, 10.0);
  EXPECT_EQ(a, b);
  fs::remove_all(dir);
}

// ------------------------------------------------------------------ parser

const std::string kCube = R"(*CONTROL_TERMINATION
1.0e-6
*PART
cube
1,1,1
*SECTION_SOLID
1
*MAT_ELASTIC
1,7850.0,2.1e11,0.3
)";

// One hexahedron, nodes 1..8 of the unit cube scaled by `s`, in the given *NODE / *ELEMENT_SOLID text.
TEST(KeywordParser, FixedLongAndCommaFormatsReadTheSameCards) {
  const fs::path dir = test::scratch_dir();
  const std::string fixed = "*NODE\n"
                            "$#   nid               x               y               z      tc      rc\n"
                            "       1             0.0             0.0             0.0\n"
                            "       2          2.5e-3             0.0             0.0       0       0\n"
                            "       3          2.5e-3          2.5e-3             0.0\n"
                            "       4             0.0          2.5e-3             0.0\n"
                            "       5             0.0             0.0          2.5e-3\n"
                            "       6          2.5e-3             0.0          2.5e-3\n"
                            "       7          2.5e-3          2.5e-3          2.5e-3\n"
                            "       8             0.0          2.5e-3          2.5e-3\n"
                            "*ELEMENT_SOLID\n"
                            "       1       1       1       2       3       4       5       6       7       8\n";
  std::string long_text = "*NODE +\n";
  std::string comma = "*NODE\n";
  const double x[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  char buf[200];
  for (int n = 0; n < 8; ++n) {
    std::snprintf(buf, sizeof buf, "%20d%20s%20s%20s\n", n + 1, x[n][0] ? "2.5e-3" : "0.0", x[n][1] ? "2.5e-3" : "0.0",
                  x[n][2] ? "2.5e-3" : "0.0");
    long_text += buf;
    std::snprintf(buf, sizeof buf, "%d, %s,%s ,%s\n", n + 1, x[n][0] ? "2.5e-3" : "0", x[n][1] ? "0.0025" : "0.",
                  x[n][2] ? "25e-4" : "0");
    comma += buf;
  }
  long_text += "*ELEMENT_SOLID+\n";
  for (int k = 0; k < 10; ++k) {
    std::snprintf(buf, sizeof buf, "%20d", k < 2 ? 1 : k - 1);
    long_text += buf;
  }
  long_text += "\n";
  comma += "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";
  const auto a = convert_text(dir, kCube + fixed);
  const auto b = convert_text(dir, kCube + long_text);
  const auto c = convert_text(dir, "*KEYWORD\n" + kCube + comma + "*END\nthis line is after *END and not read\n");
  for (const auto* conv : {&a, &b, &c}) ASSERT_FALSE(conv->refused()) << keyword::refusals(*conv);
  ASSERT_EQ(a.mesh.num_nodes(), 8u);
  EXPECT_EQ(a.mesh.coords[3 * 6 + 2], 2.5e-3);
  EXPECT_TRUE(a.mesh.coords == b.mesh.coords && a.mesh.coords == c.mesh.coords);
  EXPECT_TRUE(a.mesh.hex == b.mesh.hex && a.mesh.hex == c.mesh.hex);
  EXPECT_EQ(a.yaml, b.yaml);
  EXPECT_EQ(a.yaml, c.yaml);

  // The whole deck in long format (*KEYWORD LONG=Y): 20-character fields everywhere.
  std::string all_long = "*KEYWORD LONG=Y\n*CONTROL_TERMINATION\n              1.0e-6\n*PART\ncube\n";
  for (const char* v : {"1", "1", "1"}) all_long += std::string(19, ' ') + v;
  all_long += "\n*SECTION_SOLID\n                   1\n*MAT_ELASTIC\n                   1              7850.0"
              "              2.1e11                 0.3\n";
  const auto d = convert_text(dir, all_long + long_text.substr(long_text.find('\n') + 1).insert(0, "*NODE\n"));
  ASSERT_FALSE(d.refused()) << keyword::refusals(d);
  EXPECT_EQ(a.yaml, d.yaml);
  fs::remove_all(dir);
}

TEST(KeywordParser, IncludeIsRelativeToTheIncludingFileAndCommentsAreSkipped) {
  const fs::path dir = test::scratch_dir();
  fs::create_directories(dir / "sub");
  test::write_file(dir / "sub" / "mesh.k", "$ nodes here, elements in the file beside this one\n*INCLUDE\nelems.k\n"
                                            "*NODE\n1,0,0,0\n2,1,0,0\n$ a comment between data lines\n3,1,1,0\n4,0,1,0\n"
                                            "5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n");
  test::write_file(dir / "sub" / "elems.k", "*ELEMENT_SOLID\n$ eid pid n1..n8\n1,1,1,2,3,4,5,6,7,8\n*END\n");
  const auto c = convert_text(dir, "$ header comment\n*KEYWORD\n" + kCube + "*INCLUDE\nsub/mesh.k\n*END\n");
  ASSERT_FALSE(c.refused()) << keyword::refusals(c);
  EXPECT_EQ(c.mesh.num_nodes(), 8u);
  EXPECT_EQ(c.mesh.num_elements(), 1u);
  bool saw_elements = false;
  for (const auto& e : c.coverage)
    if (e.keyword == "ELEMENT_SOLID") saw_elements = fs::path(e.file).filename() == "elems.k" && e.line == 1;
  EXPECT_TRUE(saw_elements);
  // A file that includes itself is an error naming the *INCLUDE line.
  test::write_file(dir / "loop.k", "*KEYWORD\n*INCLUDE\nloop.k\n");
  try {
    keyword::read_deck((dir / "loop.k").string());
    ADD_FAILURE() << "include cycle not refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loop.k:3: *INCLUDE"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(KeywordParser, UnitsScaleTheMeshAndGoToTheScene) {
  const fs::path dir = test::scratch_dir();
  const auto c = convert_text(dir, kCube + "*NODE\n1,0,0,0\n2,2.5,0,0\n3,2.5,2.5,0\n4,0,2.5,0\n5,0,0,2.5\n6,2.5,0,2.5\n"
                                           "7,2.5,2.5,2.5\n8,0,2.5,2.5\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n",
                              "mm-t-s-MPa");
  ASSERT_FALSE(c.refused()) << keyword::refusals(c);
  EXPECT_EQ(c.mesh.coords[3], 2.5 * 1e-3);  // mm -> m for the .msh
  EXPECT_NE(c.yaml.find("units: mm-t-s-MPa"), std::string::npos);
  EXPECT_NE(c.yaml.find("E: 2.1e+11"), std::string::npos);  // material values as on the card: the loader converts
  fs::remove_all(dir);
}

// ------------------------------------------------------------------ refusals

TEST(KeywordRefusals, UnknownKeywordUnsupportedOptionAndFieldValueNameTheLine) {
  const fs::path dir = test::scratch_dir();
  const std::string mesh = "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                           "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";
  const auto c = convert_text(dir, kCube + mesh +                       // lines 1-20
                                       "*LOAD_BODY_Z\n1,9.81\n"         // 21: unknown keyword
                                       "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR\n1,2,3,3\n"  // 23: option
                                       "*CONTROL_TIMESTEP\n$ dtinit tssfac isdo tslimt dt2ms\n"
                                       "0.0,0.9,0,0.0,-1.0e-8\n");  // 27: DT2MS (mass scaling) not implemented
  EXPECT_TRUE(c.refused());
  const std::string file = (dir / "d.k").string();
  EXPECT_EQ(refusal(c, "LOAD_BODY_Z").rfind(file + ":21: *LOAD_BODY_Z: keyword not implemented", 0), 0u)
      << refusal(c, "LOAD_BODY_Z");
  EXPECT_EQ(refusal(c, "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR")
                .rfind(file + ":23: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR: option 'MORTAR' of "
                              "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE is not implemented", 0),
            0u)
      << refusal(c, "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR");
  EXPECT_EQ(refusal(c, "CONTROL_TIMESTEP").rfind(file + ":27: *CONTROL_TIMESTEP: field DT2MS = '-1.0e-8': not supported", 0), 0u)
      << refusal(c, "CONTROL_TIMESTEP");
  // The other cards are still reported, as used or mapped.
  for (const auto& e : c.coverage)
    if (e.keyword == "MAT_ELASTIC") {
      EXPECT_EQ(e.status, "used");
    }
  // convert_deck_file refuses the deck as a whole, listing every refusal.
  try {
    keyword::convert_deck_file(file, "SI", dir / "out.yaml");
    ADD_FAILURE() << "deck with refusals converted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(":21: *LOAD_BODY_Z"), std::string::npos);
    EXPECT_NE(what.find(":27: *CONTROL_TIMESTEP"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir / "out.yaml"));
  fs::remove_all(dir);
}

TEST(KeywordRefusals, FieldValuesTheSolverDoesNotHaveAreRefusedNotDropped) {
  const fs::path dir = test::scratch_dir();
  const auto c = convert_text(dir, "*SECTION_SOLID\n         1         3\n"      // ELFORM 3
                                   "*HOURGLASS\n1,8\n"                          // IHQ 8
                                   "*NODE\n1,0,0,0,7\n"                         // TC 7
                                   "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,7\n");    // degenerate hexahedron
  EXPECT_NE(refusal(c, "SECTION_SOLID").find(":2: *SECTION_SOLID: field ELFORM = '3'"), std::string::npos);
  EXPECT_NE(refusal(c, "HOURGLASS").find(":4: *HOURGLASS: field IHQ = '8'"), std::string::npos);
  EXPECT_NE(refusal(c, "NODE").find(":6: *NODE: field TC = '7'"), std::string::npos);
  EXPECT_NE(refusal(c, "ELEMENT_SOLID").find(":8: *ELEMENT_SOLID: field N8 = '7': degenerate"), std::string::npos)
      << refusal(c, "ELEMENT_SOLID");
  fs::remove_all(dir);
}

TEST(KeywordRefusals, SegmentSetContactIsRefusedAndSingleSurfaceZeroTakesEveryPart) {
  const fs::path dir = test::scratch_dir();
  const std::string mesh = "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                           "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";               // lines 10-20
  const std::string single = "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n0\n";
  const auto c = convert_text(dir, kCube + mesh + "*SET_SEGMENT\n1\n1,2,3,4\n"   // 21-23
                                       "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,1,0,3\n" + single);  // 24-25
  EXPECT_NE(refusal(c, "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE")
                .find(":25: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE: field SSTYP = '0': segment-set surfaces"),
            std::string::npos)
      << refusal(c, "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE");
  const auto d = convert_text(dir, kCube + mesh + single);
  ASSERT_FALSE(d.refused()) << keyword::refusals(d);
  EXPECT_NE(d.yaml.find("type: automatic_single_surface\n    parts: [part_1]"), std::string::npos) << d.yaml;
  fs::remove_all(dir);
}

// Two unit cubes stacked with their own nodes (parts 1 and 2) and a tiebreak contact between them.
std::string two_cubes(const std::string& tiebreak_card) {
  return "*CONTROL_TERMINATION\n1.0e-6\n*PART\nlower\n1,1,1\n*PART\nupper\n2,1,1\n*SECTION_SOLID\n1\n"
         "*MAT_ELASTIC\n1,7850.0,2.1e11,0.3\n"
         "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
         "9,0,0,1\n10,1,0,1\n11,1,1,1\n12,0,1,1\n13,0,0,2\n14,1,0,2\n15,1,1,2\n16,0,1,2\n"
         "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n2,2,9,10,11,12,13,14,15,16\n"
         "*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK\n2,1,3,3\n0.3\n\n" + tiebreak_card;
}

TEST(KeywordDecks, TiebreakContactMapsCardFourOntoATiebreakContact) {
  const fs::path dir = test::scratch_dir();
  const auto c = convert_text(dir, two_cubes("9,6.0e7,5.0e7,-2.0,765.0,1250.0,1.0,1.0e14\n"));
  ASSERT_FALSE(c.refused()) << keyword::refusals(c);
  for (const char* want : {"type: tiebreak_surface_to_surface", "surfaces: [[part_2], [part_1]]", "OPTION: 9"})
    EXPECT_NE(c.yaml.find(want), std::string::npos) << want << "\n" << c.yaml;
  const auto value = [&](const std::string& key) {
    const auto at = c.yaml.find("    " + key + ": ");
    return at == std::string::npos ? std::nan("") : std::stod(c.yaml.substr(at + key.size() + 6));
  };
  const std::pair<const char*, double> fields[] = {{"NFLS", 6e7}, {"SFLS", 5e7}, {"PARAM", -2}, {"ERATEN", 765},
                                                   {"ERATES", 1250}, {"CT2CN", 1}, {"CN", 1e14}, {"FS", 0.3}};
  for (const auto& [key, v] : fields) EXPECT_EQ(value(key), v) << key << "\n" << c.yaml;
  fs::remove_all(dir);
}

TEST(KeywordRefusals, TiebreakWithoutCnOrWithAnUnknownOptionIsRefused) {
  const fs::path dir = test::scratch_dir();
  const auto no_cn = convert_text(dir, two_cubes("9,6.0e7,5.0e7,1.0,765.0,1250.0,1.0\n"));
  EXPECT_NE(refusal(no_cn, "CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK").find("field CN"), std::string::npos)
      << keyword::refusals(no_cn);
  const auto option = convert_text(dir, two_cubes("8,6.0e7,5.0e7,1.0,765.0,1250.0,1.0,1.0e14\n"));
  EXPECT_NE(refusal(option, "CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK").find("field OPTION = '8'"),
            std::string::npos)
      << keyword::refusals(option);
  fs::remove_all(dir);
}

}  // namespace
