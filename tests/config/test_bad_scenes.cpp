// config/scene_loader: a table of malformed scenes. Each case edits one spot of a small valid scene
// (kBase, line numbers in the comment) and checks the InputError message: exact file:line:col, key
// path and the what/found/allowed parts. Three further cases load tests/data/scenes/bad_*.yaml.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "core/error.hpp"

namespace cfg = plyimpact::config;

namespace {

// clang-format off
const std::string kBase =
    "units: SI\n"                                   //  1
    "control:\n"                                    //  2
    "  termination_time: 1.0e-5\n"                  //  3
    "materials:\n"                                  //  4
    "  steel:\n"                                    //  5
    "    card: MAT_001\n"                           //  6
    "    RO: 7850\n"                                //  7
    "    E: 210 GPa\n"                              //  8
    "    PR: 0.3\n"                                 //  9
    "  ply:\n"                                      // 10
    "    card: MAT_002\n"                           // 11
    "    RO: 1550\n"                                // 12
    "    EA: 157 GPa\n"                             // 13
    "    EB: 8.5 GPa\n"                             // 14
    "    EC: 8.5 GPa\n"                             // 15
    "    PRBA: 0.019\n"                             // 16
    "    PRCA: 0.019\n"                             // 17
    "    PRCB: 0.53\n"                              // 18
    "    GAB: 4.2 GPa\n"                            // 19
    "    GBC: 2.2 GPa\n"                            // 20
    "    GCA: 4.2 GPa\n"                            // 21
    "sections:\n"                                   // 22
    "  hex1: {ELFORM: 1, IHQ: 4}\n"                 // 23
    "parts:\n"                                      // 24
    "  bar: {material: steel, section: hex1}\n"     // 25
    "mesh:\n"                                       // 26
    "  boxes:\n"                                    // 27
    "    - part: bar\n"                             // 28
    "      size: [0.1, 0.01, 0.01]\n"               // 29
    "      elements: [10, 1, 1]\n"                  // 30
    "node_sets:\n"                                  // 31
    "  left: {plane: {axis: x, value: 0}}\n"        // 32
    "boundary_conditions:\n"                        // 33
    "  - node_set: left\n"                          // 34
    "    velocity: {dofs: [x], curve: [[0, 0], [1.0e-6, 10]]}\n";  // 35
// clang-format on

struct BadCase {
  const char* name;
  std::string from, to;                 // kBase with `from` (must occur once) replaced by `to`
  std::vector<std::string> fragments;   // all must appear in the message
};

const std::string kFile = "scenes/bad.yaml";

std::string edited(const BadCase& c) {
  const auto pos = kBase.find(c.from);
  EXPECT_NE(pos, std::string::npos) << c.name << ": '" << c.from << "' not in the base scene";
  EXPECT_EQ(kBase.find(c.from, pos + 1), std::string::npos) << c.name << ": '" << c.from << "' occurs twice";
  std::string s = kBase;
  if (pos != std::string::npos) s.replace(pos, c.from.size(), c.to);
  return s;
}

std::string error_of(const std::string& text, const std::string& label) {
  try {
    cfg::load_scene_from_string(text, label);
  } catch (const plyimpact::InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

const std::vector<BadCase> kCases = {
    {"termination_contact_unknown_contact", "  termination_time: 1.0e-5\n",
     "  termination_time: 1.0e-5\n  termination_contact: {contact: tup, DUR: 1 us}\n",
     {"scenes/bad.yaml:4:", "control.termination_contact.contact", "'tup'"}},
    {"termination_contact_negative_dur", "  termination_time: 1.0e-5\n",
     "  termination_time: 1.0e-5\n  termination_contact: {DUR: -1 us}\n",
     {"scenes/bad.yaml:4:", "control.termination_contact.DUR", "DUR (duration of no force before the stop)"}},
    {"unknown_key", "    EA: 157 GPa", "    EAA: 157 GPa",
     {"scenes/bad.yaml:13:5: materials.ply.EAA: unknown key 'EAA' (did you mean 'EA'?)", "; found 'EAA'",
      "; allowed keys card, RO, EA,"}},
    {"unknown_top_level_key", "mesh:\n", "mesj:\n",
     {"scenes/bad.yaml:26:1: mesj: unknown key 'mesj' (did you mean 'mesh'?)"}},
    {"missing_required_key", "    EA: 157 GPa\n", "",
     {"scenes/bad.yaml:11:5: materials.ply.EA: missing required key 'EA'", "; found a mapping with keys [card, RO, EB",
      "; allowed a stress (e.g. MPa, GPa, Pa)"}},
    {"missing_units", "units: SI\n", "",
     {"scenes/bad.yaml:1:1: units: missing required key 'units'", "allowed SI, mm-t-s-MPa, mm-kg-ms-GPa"}},
    {"bad_unit_system", "units: SI", "units: furlongs",
     {"scenes/bad.yaml:1:8: units: unknown unit system 'furlongs'; found 'furlongs'; allowed SI, mm-t-s-MPa"}},
    {"wrong_type_list_for_number", "    E: 210 GPa", "    E: [210, 0]",
     {"scenes/bad.yaml:8:8: materials.steel.E: wrong type, expected a single value; found [210, 0]",
      "allowed a plain number (scene units, SI) or '<number> <unit>' for a stress"}},
    {"wrong_type_map_for_list", "    velocity: {dofs: [x], curve: [[0, 0], [1.0e-6, 10]]}", "    fix: {x: 1}",
     {"scenes/bad.yaml:35:10: boundary_conditions[0].fix: wrong type, expected a list; found a mapping with keys [x]"}},
    {"bad_unit_dimension", "    E: 210 GPa", "    E: 210 mm",
     {"scenes/bad.yaml:8:8: materials.steel.E: expected a stress (e.g. MPa, GPa, Pa); got 'mm' (a length)",
      "; found '210 mm'"}},
    {"unknown_unit", "    E: 210 GPa", "    E: 210 Gpa",
     {"scenes/bad.yaml:8:8: materials.steel.E: unknown unit 'Gpa' in unit 'Gpa'; found '210 Gpa'"}},
    {"number_with_trailing_garbage", "    RO: 7850", "    RO: 12abc",
     {"scenes/bad.yaml:7:9: materials.steel.RO: unknown unit 'abc'", "; found '12abc'"}},
    {"negative_density", "    RO: 7850", "    RO: -7850",
     {"scenes/bad.yaml:7:9: materials.steel.RO: density must be > 0; found '-7850' (= -7850 SI); allowed RO > 0"}},
    {"poisson_half", "    PR: 0.3", "    PR: 0.5",
     {"scenes/bad.yaml:9:9: materials.steel.PR: Poisson's ratio must be in (-1, 0.5); found '0.5'"}},
    {"zero_modulus", "    GBC: 2.2 GPa", "    GBC: 0 GPa", {"scenes/bad.yaml:20:10: materials.ply.GBC: GBC must be > 0"}},
    {"prba_too_large", "    PRBA: 0.019", "    PRBA: 0.3",
     {"scenes/bad.yaml:16:11: materials.ply.PRBA: |PRBA| must be < sqrt(EB/EA) = 0.2326", "; found '0.3'",
      "; allowed |PRBA| < 0.2326"}},
    {"unknown_card", "    card: MAT_002", "    card: MAT_058",
     {"scenes/bad.yaml:11:11: materials.ply.card: unknown material card; found 'MAT_058'; allowed MAT_001"}},
    {"bad_elform", "{ELFORM: 1, IHQ: 4}", "{ELFORM: 3, IHQ: 4}",
     {"scenes/bad.yaml:23:18: sections.hex1.ELFORM: ELFORM must be one of 1, 2, -2; found '3'; allowed one of 1, 2, -2"}},
    {"bad_ihq", "{ELFORM: 1, IHQ: 4}", "{ELFORM: 1, IHQ: 7}",
     {"scenes/bad.yaml:23:26: sections.hex1.IHQ: IHQ must be one of 1, 2, 3, 4, 5, 6; found '7'"}},
    {"bad_qm_ihq6", "{ELFORM: 1, IHQ: 4}", "{ELFORM: 1, IHQ: 6, QM: 1.5}",
     {"scenes/bad.yaml:23:33: sections.hex1.QM: QM must be in (0, 1]"}},
    {"bad_qm", "{ELFORM: 1, IHQ: 4}", "{ELFORM: 1, IHQ: 4, QM: 0.6}",
     {"scenes/bad.yaml:23:33: sections.hex1.QM: QM must be in (0, 0.5]"}},
    {"unknown_material_reference", "{material: steel,", "{material: stel,",
     {"scenes/bad.yaml:25:19: parts.bar.material: unknown material 'stel' (did you mean 'steel'?); found 'stel'",
      "; allowed a material defined under 'materials': steel, ply"}},
    {"unknown_section_reference", "section: hex1}", "section: tet4}",
     {"scenes/bad.yaml:25:35: parts.bar.section: unknown section 'tet4'", "allowed a section defined under 'sections': hex1"}},
    {"duplicate_part_id", "  bar: {material: steel, section: hex1}\n",
     "  bar: {material: steel, section: hex1, id: 3}\n  bar2: {material: ply, section: hex1, id: 3}\n",
     {"scenes/bad.yaml:26:44: parts.bar2.id: duplicate part id 3 (already used by part 'bar')"}},
    {"unknown_part_in_box", "    - part: bar", "    - part: baz",
     {"scenes/bad.yaml:28:13: mesh.boxes[0].part: unknown part 'baz' (did you mean 'bar'?)"}},
    {"unknown_node_set", "  - node_set: left", "  - node_set: lft",
     {"scenes/bad.yaml:34:15: boundary_conditions[0].node_set: unknown node set 'lft' (did you mean 'left'?)",
      "allowed a node set defined under 'node_sets': left"}},
    {"decreasing_curve_times", "[[0, 0], [1.0e-6, 10]]", "[[0, 0], [1.0e-6, 10], [5.0e-7, 10]]",
     {"scenes/bad.yaml:35:58: boundary_conditions[0].velocity.curve[2][0]: curve times must be strictly increasing",
      "; found '5.0e-7'"}},
    {"empty_curve", "[[0, 0], [1.0e-6, 10]]", "[]",
     {"scenes/bad.yaml:35:34: boundary_conditions[0].velocity.curve: the list must not be empty"}},
    {"bad_dof", "{dofs: [x],", "{dofs: [q],",
     {"scenes/bad.yaml:35:23: boundary_conditions[0].velocity.dofs[0]: invalid value; found 'q'; allowed one of x, y, z"}},
    {"value_and_curve", "{dofs: [x], curve:", "{dofs: [x], value: 3, curve:",
     {"scenes/bad.yaml:35:15: boundary_conditions[0].velocity: needs exactly one of 'value' or 'curve', not several"}},
    {"box_zero_size", "size: [0.1, 0.01, 0.01]", "size: [0.1, 0, 0.01]",
     {"scenes/bad.yaml:29:19: mesh.boxes[0].size[1]: box size must be > 0; found '0'"}},
    {"elements_zero", "elements: [10, 1, 1]", "elements: [10, 0, 1]",
     {"scenes/bad.yaml:30:22: mesh.boxes[0].elements[1]: element count must be >= 1; found '0'"}},
    {"elements_fraction", "elements: [10, 1, 1]", "elements: [10, 1.5, 1]",
     {"scenes/bad.yaml:30:22: mesh.boxes[0].elements[1]: expected an integer; found '1.5'; allowed an integer >= 1"}},
    {"elements_missing", "      elements: [10, 1, 1]\n", "",
     {"scenes/bad.yaml:28:7: mesh.boxes[0].elements: missing required key 'elements'"}},
    {"bad_plane_axis", "axis: x", "axis: w",
     {"scenes/bad.yaml:32:24: node_sets.left.plane.axis: invalid value; found 'w'; allowed one of x, y, z"}},
    {"two_selectors", "{plane: {axis: x, value: 0}}", "{plane: {axis: x, value: 0}, part: bar}",
     {"scenes/bad.yaml:32:9: node_sets.left: needs exactly one of 'plane', 'box' or 'part', not several"}},
    {"node_set_box_min_gt_max", "{plane: {axis: x, value: 0}}", "{box: {min: [0, 0, 1], max: [1, 1, 0]}}",
     {"scenes/bad.yaml:32:44: node_sets.left.box.max[2]: box max must be >= min"}},
    {"zero_termination_time", "termination_time: 1.0e-5", "termination_time: 0",
     {"scenes/bad.yaml:3:21: control.termination_time: termination time must be > 0"}},
    {"tssfac_too_large", "termination_time: 1.0e-5", "termination_time: 1.0e-5\n  tssfac: 1.5",
     {"scenes/bad.yaml:4:11: control.tssfac: tssfac must be in (0, 1]"}},
    {"termination_time_not_a_time", "termination_time: 1.0e-5", "termination_time: 5 m/s",
     {"scenes/bad.yaml:3:21: control.termination_time: expected a time (e.g. s, ms, us); got 'm/s' (a velocity)"}},
    {"aopt_parallel_vectors", "    GCA: 4.2 GPa\n", "    GCA: 4.2 GPa\n    AOPT: 2\n    A: [1, 0, 0]\n    D: [2, 0, 0]\n",
     {"scenes/bad.yaml:24:8: materials.ply.D: with AOPT 2 the vectors A and D must not be parallel"}},
    {"bad_aopt", "    GCA: 4.2 GPa\n", "    GCA: 4.2 GPa\n    AOPT: 1\n",
     {"scenes/bad.yaml:22:11: materials.ply.AOPT: AOPT must be one of 0, 2, 3"}},
    {"initial_velocity_part_and_node_set", "[[0, 0], [1.0e-6, 10]]}\n",
     "[[0, 0], [1.0e-6, 10]]}\ninitial_velocity:\n  - {part: bar, node_set: left, velocity: [0, 0, 1]}\n",
     {"scenes/bad.yaml:37:5: initial_velocity[0]: needs exactly one of 'part' or 'node_set', not several"}},
    {"yaml_syntax_error", "  bar: {material: steel, section: hex1}", "  bar: {material: steel, section: hex1",
     {"scenes/bad.yaml:26:5: YAML syntax error: end of map flow not found"}},
    {"empty_value_points_at_key", "    E: 210 GPa", "    E:",
     {"scenes/bad.yaml:8:5: materials.steel.E: missing value; found an empty value"}},
    {"duplicate_key", "    PR: 0.3\n", "    PR: 0.3\n    PR: 0.2\n",
     {"scenes/bad.yaml:10:5: materials.steel.PR: duplicate key 'PR'"}},
};

// Readable test names in failure output instead of a byte dump.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class BadScene : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScene, MessageHasLocationKeyPathAndExplanation) {
  const BadCase& c = GetParam();
  const std::string message = error_of(edited(c), kFile);
  for (const auto& frag : c.fragments)
    EXPECT_NE(message.find(frag), std::string::npos) << "case " << c.name << "\n  expected: " << frag
                                                     << "\n  message:  " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
}

INSTANTIATE_TEST_SUITE_P(SceneLoader, BadScene, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SceneLoaderBadFiles, FilesInTestData) {
  const std::string dir = std::string(PLYIMPACT_SOURCE_DIR) + "/tests/data/scenes/";
  struct FileCase {
    const char* file;
    const char* fragment;
  };
  const FileCase cases[] = {
      {"bad_syntax.yaml", "bad_syntax.yaml:8:1: YAML syntax error"},
      {"bad_missing_units.yaml", "bad_missing_units.yaml:2:1: units: missing required key 'units'"},
      {"bad_unknown_key.yaml", "bad_unknown_key.yaml:10:5: materials.steel.EE: unknown key 'EE' (did you mean 'E'?)"},
  };
  for (const auto& c : cases) {
    std::string message = "<no InputError>";
    try {
      cfg::load_scene(dir + c.file);
    } catch (const plyimpact::InputError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find(c.fragment), std::string::npos) << "expected: " << c.fragment << "\nmessage: " << message;
  }
}

}  // namespace
