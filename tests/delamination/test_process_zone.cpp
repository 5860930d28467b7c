// process_zone_elements on the laminate's interfaces: each segment's strengths lowered so that the
// cohesive zone spans N segments of its own length (Turon, Davila, Camanho & Costa 2007, Eng. Fract.
// Mech. 74:1665), on a graded mesh where the segments differ.
// Independent answer: T07's strength for N elements of length l_e, written out here,
//   tau = sqrt(9 pi E G_c / (32 N l_e)),  E = the smaller EC of the two plies,
// with G_c = ERATEN for NFLS and ERATES for SFLS, applied where it is below the card's. Inside the
// refined zone every segment around a pair is the zone's 1 mm square, so the pair's strengths are
// tau at l_e = 1 mm to round-off (1e-9); outside, the graded segments are 1 to 4 mm, so every pair
// lies between tau(4 mm) and tau(1 mm). The whole chain against the LEFM answer (a DCB's peak load
// and G_Ic by ASTM D5528) is test_cohesive_zone_length and test_dcb_scene.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "interface/interface_tiebreaks.hpp"
#include "laminate_scene_support.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"

namespace plyimpact {
namespace {

constexpr double kEsoft = 5e9, kGIc = 765, kGIIc = 1250, kN = 3;  // the scene below

double turon(double g_c, double length) {
  return std::sqrt(9 * std::numbers::pi * kEsoft * g_c / (32 * kN * length));
}

// A [0/90] plate 24 x 12 mm, 4 mm elements graded to a 4 x 4 mm zone of 1 mm ones at the centre;
// the 90 degree ply's card has EC 5 GPa, the 0 degree ply's 10 GPa.
std::string scene(const std::string& interfaces) {
  return "units: mm-t-s-MPa\n"
         "control: {termination_time: 1.0e-5}\n"
         "materials:\n"
         "  stiff: {card: MAT_002, RO: 1600 kg/m^3, EA: 120 GPa, EB: 10 GPa, EC: 10 GPa, PRBA: 0.025, PRCA: 0.025,\n"
         "          PRCB: 0.45, GAB: 5 GPa, GBC: 3.5 GPa, GCA: 5 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
         "  soft: {card: MAT_002, RO: 1600 kg/m^3, EA: 120 GPa, EB: 10 GPa, EC: 5 GPa, PRBA: 0.025, PRCA: 0.025,\n"
         "          PRCB: 0.45, GAB: 5 GPa, GBC: 3.5 GPa, GCA: 5 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
         "laminate:\n"
         "  length: 24\n  width: 12\n  ply_thickness: 0.25\n  stacking: [0, 90]\n"
         "  material: {0: stiff, 90: soft}\n  section: s\n  element_size: 4\n"
         "  refined_zone: {size: [4, 4], element_size: 1}\n"
         "  interfaces: " + interfaces + "\n";
}

const std::string kTiebreak = "{select: all, model: tiebreak, OPTION: 9, NFLS: 60 MPa, SFLS: 50 MPa, ERATEN: 765 J/m^2, "
                              "ERATES: 1250 J/m^2, PARAM: 1, CN: 100 kN/mm^3, CT2CN: 1, process_zone_elements: 3}";

model::Model build(const std::string& yaml) { return test::build_laminate(yaml, "pz.yaml"); }

bool in_zone(const double* x, double half) { return std::abs(x[0] - 12e-3) < half && std::abs(x[1] - 6e-3) < half; }

TEST(ProcessZone, EachPairGetsTheStrengthOfItsOwnSegments) {
  const model::Model m = build(scene(kTiebreak));
  ASSERT_EQ(m.interfaces.size(), 1u);
  const auto& itf = m.interfaces[0];
  EXPECT_EQ(itf.transverse_modulus, kEsoft);
  const cohesive::TiebreakPairs pairs = interface::make_interface_pairs(m, itf);
  const double n1 = turon(kGIc, 1e-3), s1 = turon(kGIIc, 1e-3), n4 = turon(kGIc, 4e-3), s4 = turon(kGIIc, 4e-3);
  ASSERT_LT(s1, 50e6);  // both modes lowered even in the zone
  std::size_t inside = 0, coarser = 0;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const double nfls = pairs.laws().nfls(p), sfls = pairs.laws().sfls(p);
    if (in_zone(&m.X[3 * std::size_t(itf.lower_nodes[p])], 1e-3 + 1e-9)) {  // all four segments 1 mm
      ++inside;
      ASSERT_NEAR(nfls, n1, 1e-9 * n1) << "pair " << p;
      ASSERT_NEAR(sfls, s1, 1e-9 * s1) << "pair " << p;
    }
    ASSERT_GE(nfls, n4 * (1 - 1e-9)) << "pair " << p;
    ASSERT_LE(nfls, n1 * (1 + 1e-9)) << "pair " << p;
    ASSERT_GE(sfls, s4 * (1 - 1e-9)) << "pair " << p;
    ASSERT_LE(sfls, s1 * (1 + 1e-9)) << "pair " << p;
    coarser += nfls < n1 * (1 - 1e-6);
  }
  EXPECT_EQ(inside, 9u);  // the 3 x 3 interior nodes of the 4 x 4 mm zone
  EXPECT_GT(coarser, pairs.size() / 2);
  EXPECT_EQ(pairs.laws().num_lowered(), pairs.size());
  // The stiffness and the energies are the card's: only the onsets move.
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    ASSERT_EQ(pairs.law(p).kn, pairs.law().kn);
    ASSERT_EQ(pairs.law(p).gic, kGIc);
    ASSERT_EQ(pairs.law(p).giic, kGIIc);
  }
  const std::string detail = interface::InterfaceTiebreaks::describe(m).detail;
  EXPECT_NE(detail.find("strengths for 3 segments in the process zone (E 5 GPa)"), std::string::npos) << detail;
}

TEST(ProcessZone, CohesiveElementsGetTheStrengthOfTheirOwnSegment) {
  const model::Model m = build(scene("{select: all, model: cohesive, T: 60 MPa, S: 50 MPa, GIC: 765 J/m^2, "
                                     "GIIC: 1250 J/m^2, XMU: 1, EN: 100 kN/mm^3, ET: 100 kN/mm^3, "
                                     "process_zone_elements: 3}"));
  const auto& itf = m.interfaces[0];
  const cohesive::CohesiveElements elements = interface::make_interface_cohesive(m, itf);
  const double n1 = turon(kGIc, 1e-3), n4 = turon(kGIc, 4e-3);
  std::size_t inside = 0;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    double centre[3] = {0, 0, 0};
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) centre[i] += 0.25 * m.X[3 * std::size_t(elements.nodes()[8 * e + a]) + i];
    const double nfls = elements.laws().nfls(e);
    if (in_zone(centre, 2e-3)) {
      ++inside;
      ASSERT_NEAR(nfls, n1, 1e-9 * n1) << "element " << e;
    }
    ASSERT_GE(nfls, n4 * (1 - 1e-9)) << "element " << e;
    ASSERT_LE(nfls, n1 * (1 + 1e-9)) << "element " << e;
  }
  EXPECT_EQ(inside, 16u);
}

TEST(ProcessZone, WithoutTheKeyEveryPointHasTheCardsStrengths) {
  std::string law = kTiebreak;
  law.replace(law.find(", process_zone_elements: 3"), std::string(", process_zone_elements: 3").size(), "");
  const model::Model m = build(scene(law));
  const cohesive::TiebreakPairs pairs = interface::make_interface_pairs(m, m.interfaces[0]);
  EXPECT_EQ(pairs.laws().num_laws(), 1u);
  EXPECT_EQ(pairs.laws().num_lowered(), 0u);
  EXPECT_EQ(pairs.laws().nfls(0), 60e6);
}

std::string error_of(const std::string& yaml) { return test::laminate_error(yaml, "pz.yaml"); }

TEST(ProcessZone, BadValuesAreRefusedWithTheKey) {
  std::string below_one = kTiebreak;
  below_one.replace(below_one.find("process_zone_elements: 3"), 24, "process_zone_elements: 0.5");
  std::string e = error_of(scene(below_one));
  EXPECT_NE(e.find("pz.yaml:19:"), std::string::npos) << e;
  EXPECT_NE(e.find("laminate.interfaces.process_zone_elements"), std::string::npos) << e;
  EXPECT_NE(e.find("0.5"), std::string::npos) << e;

  e = error_of(scene("{select: all, model: tiebreak, OPTION: 6, NFLS: 60 MPa, SFLS: 50 MPa, PARAM: 0.01 mm, "
                     "CN: 100 kN/mm^3, process_zone_elements: 3}"));
  EXPECT_NE(e.find("laminate.interfaces.process_zone_elements"), std::string::npos) << e;
  EXPECT_NE(e.find("OPTION 6"), std::string::npos) << e;
  EXPECT_NE(e.find("OPTION 7 or 9"), std::string::npos) << e;
}

}  // namespace
}  // namespace plyimpact
