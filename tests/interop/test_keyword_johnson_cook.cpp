// Keyword decks with the impactor materials: *MAT_JOHNSON_COOK with *EOS_GRUNEISEN (through the
// part's EOSID) gives the history of the same YAML scene byte for byte (see test_keyword_decks.cpp
// for why the two must be identical), and *MAT_SIMPLIFIED_JOHNSON_COOK / *EOS_LINEAR_POLYNOMIAL map
// field by field; what the code does not implement is refused with the line and the field.
#include <gtest/gtest.h>

#include <filesystem>

#include "deck_support.hpp"

using namespace plyimpact;
namespace fs = std::filesystem;

namespace {

using test::convert_text;
using test::kDecks;
using test::refusal;

const std::string kCubeMesh = "*CONTROL_TERMINATION\n1.0e-6\n*SECTION_SOLID\n1\n"
                              "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                              "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";

TEST(KeywordJohnsonCook, RodWithGruneisenEosGivesTheHistoryOfTheYamlScene) {
  const fs::path dir = test::scratch_dir();
  const std::string yaml = R"(units: SI
control: {termination_time: 5.0e-5, tssfac: 0.9}
output: {interval: 2.5e-5, history_interval: 1.0e-6}
materials:
  mat_1:
    card: MAT_015
    RO: 8960
    G: 46000000000
    A: 90000000
    B: 292000000
    N: 0.31
    C: 0.025
    M: 1.09
    TM: 1356
    TR: 295
    EPSO: 1
    CP: 383
    SPALL: 1
    eos: {card: EOS_GRUNEISEN, C: 3940, S1: 1.489, GAMAO: 2.02, A: 0.47}
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
  - {part: part_1, velocity: [0, 0, -150]}
rigid_walls:
  - {name: wall_1, point: [0, 0, 0], normal: [0, 0, 1]}
)";
  const auto conv = keyword::convert_deck_file((kDecks / "rod_wall_jc.k").string(), "SI", dir / "deck.yaml");
  for (const auto& e : conv.coverage)
    if (e.keyword == "EOS_GRUNEISEN") {
      EXPECT_EQ(e.status, "mapped") << e.note;
    }
  const std::string text = test::read_file(dir / "deck.yaml");
  EXPECT_NE(text.find("eos: {card: EOS_GRUNEISEN, C: 3940, S1: 1.489, GAMAO: 2.02, A: 0.47}"), std::string::npos) << text;
  const std::string a = test::run_history(config::load_scene((dir / "deck.yaml").string()), dir / "deck_run");
  const std::string b = test::yaml_history(yaml, dir);
  EXPECT_GT(std::count(a.begin(), a.end(), '\n'), 45);
  EXPECT_EQ(a, b);
  fs::remove_all(dir);
}

TEST(KeywordJohnsonCook, SimplifiedCardAndPolynomialEosMapFieldByField) {
  const fs::path dir = test::scratch_dir();
  const auto c = convert_text(dir, kCubeMesh +
                                       "*PART\nsteel\n1,1,1\n"
                                       "*MAT_SIMPLIFIED_JOHNSON_COOK\n"
                                       "1,7850.0,2.1e11,0.3,0\n"
                                       "7.92e8,5.10e8,0.26,0.014,0.8,1.0e28,2.0e9,1.0\n");
  ASSERT_FALSE(c.refused()) << keyword::refusals(c);
  // Every field under its card name, in the deck's numbers (shortest round-trip text); SIGMAX 1e28 is
  // the card's "no cap" and is left out.
  for (const char* field : {"card: MAT_098\n", "RO: 7850\n", "E: 2.1e+11\n", "PR: 0.3\n", "A: 7.92e+08\n", "B: 5.1e+08\n",
                            "N: 0.26\n", "C: 0.014\n", "PSFAIL: 0.8\n", "SIGSAT: 2e+09\n", "EPSO: 1\n"})
    EXPECT_NE(c.yaml.find(std::string("    ") + field), std::string::npos) << field << " in\n" << c.yaml;
  EXPECT_EQ(c.yaml.find("SIGMAX"), std::string::npos);
  const auto d = convert_text(dir, kCubeMesh +
                                       "*PART\ncu\n1,1,1,7\n"
                                       "*MAT_JOHNSON_COOK\n1,8960.0,4.6e10\n9.0e7,2.92e8,0.31,0.0,1.09,1356,295\n\n\n"
                                       "*EOS_LINEAR_POLYNOMIAL\n7,0.0,1.37e11,1.8e11,0.0,2.0,0.0,0.0\n");
  ASSERT_FALSE(d.refused()) << keyword::refusals(d);
  EXPECT_NE(d.yaml.find("eos: {card: EOS_LINEAR_POLYNOMIAL, C0: 0, C1: 1.37e+11, C2: 1.8e+11, C3: 0, C4: 2, C5: 0, C6: 0}"),
            std::string::npos)
      << d.yaml;
  fs::remove_all(dir);
}

TEST(KeywordJohnsonCook, UnimplementedFieldsAndEosUsesAreRefusedWithTheirLine) {
  const fs::path dir = test::scratch_dir();
  // Line 20: RATEOP 1 (Huh-Kang); the EOS card's V0 (line 26); EOSID on an elastic part.
  const auto c = convert_text(dir, kCubeMesh +
                                       "*PART\ncu\n1,1,1,7\n"
                                       "*MAT_JOHNSON_COOK\n1,8960.0,4.6e10,,,,0,1\n9.0e7,2.92e8,0.31\n\n\n"
                                       "*EOS_GRUNEISEN\n7,3940.0,1.489\n0.9\n");
  EXPECT_NE(refusal(c, "MAT_JOHNSON_COOK").find(":20: *MAT_JOHNSON_COOK: field RATEOP = '1'"), std::string::npos)
      << refusal(c, "MAT_JOHNSON_COOK");
  EXPECT_NE(refusal(c, "EOS_GRUNEISEN").find(":26: *EOS_GRUNEISEN: field V0 = '0.9'"), std::string::npos)
      << refusal(c, "EOS_GRUNEISEN");
  const auto e = convert_text(dir, kCubeMesh + "*PART\nsteel\n1,1,1,7\n*MAT_ELASTIC\n1,7850.0,2.1e11,0.3\n"
                                                "*EOS_GRUNEISEN\n7,3940.0,1.489\n");
  EXPECT_NE(refusal(e, "PART").find("EOSID 7 on a *MAT_001 part"), std::string::npos) << keyword::refusals(e);
  fs::remove_all(dir);
}

}  // namespace
