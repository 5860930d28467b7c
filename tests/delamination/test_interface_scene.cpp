// The laminate's `interfaces:` law schema and the model it builds:
//  - a tiebreak law keeps the duplicated pairs apart, and each node of a pair carries the lumped
//    mass of its own ply (checked against rho A t / 8 per element corner, with plies of different
//    thickness so the two sides differ), total mass conserved;
//  - `model: merged` (the default) bonds the pairs: the upper duplicates are massless and unused;
//  - units (MPa, J/m^2, N/mm^3) reach the law in SI; a per-interface override replaces only its keys;
//  - bad input is refused with file:line:col, the key and what is allowed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "mesh/scene_mesher.hpp"
#include "interface/interface_tiebreaks.hpp"
#include "laminate_scene_support.hpp"
#include "model/model.hpp"

namespace plyimpact {
namespace {

std::string scene(const std::string& interfaces, const std::string& extra = "") {
  return "units: mm-t-s-MPa\n"
         "control: {termination_time: 1.0e-5}\n"
         "materials:\n"
         "  ply: {card: MAT_002, RO: 1600 kg/m^3, EA: 120 GPa, EB: 10 GPa, EC: 10 GPa, PRBA: 0.025, PRCA: 0.025,\n"
         "        PRCB: 0.45, GAB: 5 GPa, GBC: 3.5 GPa, GCA: 5 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
         "laminate:\n"
         "  length: 4\n  width: 2\n  ply_thickness: [0.5, 0.25, 0.25]\n  stacking: [0, 90, 90]\n"
         "  material: ply\n  section: s\n  element_size: 1\n"
         "  interfaces: " + interfaces + "\n" + extra;
}

const std::string kLaw = "OPTION: 9, NFLS: 60 MPa, SFLS: 50 MPa, ERATEN: 765 J/m^2, ERATES: 1250 J/m^2, PARAM: 1, "
                         "CN: 100 kN/mm^3, CT2CN: 1";

model::Model build(const std::string& yaml) { return test::build_laminate(yaml, "itf.yaml"); }

std::string error_of(const std::string& yaml) { return test::laminate_error(yaml, "itf.yaml"); }

TEST(InterfaceScene, TiebreakKeepsPairsApartWithTheirOwnPlysMass) {
  const model::Model m = build(scene("{select: angle-change, model: tiebreak, " + kLaw + "}"));
  ASSERT_EQ(m.interfaces.size(), 1u);  // only 0/90 changes angle
  const auto& itf = m.interfaces[0];
  ASSERT_TRUE(itf.tiebreak);
  EXPECT_FALSE(m.interfaces_bonded);
  const auto& law = itf.tiebreak->law;
  EXPECT_DOUBLE_EQ(law.NFLS, 60e6);
  EXPECT_DOUBLE_EQ(law.SFLS, 50e6);
  EXPECT_DOUBLE_EQ(law.ERATEN, 765);
  EXPECT_DOUBLE_EQ(law.CN, 1e14);
  // Element corner mass rho (1 mm x 1 mm x t) / 8; a pair node gets it from each element of its own
  // ply around it (1, 2 or 4), the same count on both sides: lower/upper = 0.5 / 0.25.
  const double corner_lower = 1600 * 1e-6 * 0.5e-3 / 8, corner_upper = 1600 * 1e-6 * 0.25e-3 / 8;
  for (std::size_t p = 0; p < itf.num_pairs(); ++p) {
    const double ml = m.mass[itf.lower_nodes[p]], mu = m.mass[itf.upper_nodes[p]];
    const double n = std::round(ml / corner_lower);
    EXPECT_TRUE(n == 1 || n == 2 || n == 4);
    EXPECT_NEAR(ml, n * corner_lower, 1e-12 * ml);
    EXPECT_NEAR(mu, n * corner_upper, 1e-12 * mu) << "pair " << p;
  }
  double total = 0;
  for (double v : m.mass) total += v;
  EXPECT_NEAR(total, 1600 * 4e-3 * 2e-3 * 1e-3, 1e-12);
}

// A pair whose ply is gone on one side joins nothing: once every element around its upper node has
// eroded it is released for good (no force, whatever the nodes do), while its neighbours, whose
// nodes keep a live element, stay. Independent answer: the mesh's own connectivity (a corner node of
// a ply belongs to one element of that ply).
TEST(InterfaceScene, PairsWhosePlyErodedAwayAreReleased) {
  const model::Model m = build(scene("{select: angle-change, model: tiebreak, " + kLaw + "}"));
  ASSERT_EQ(m.interfaces.size(), 1u);
  const auto& itf = m.interfaces[0];
  interface::InterfaceTiebreaks tiebreaks(m, 1.0);
  std::size_t upper_block = m.blocks.size();
  for (const auto& part : m.parts)
    if (part.name == "ply_2_90") upper_block = std::size_t(part.block);
  ASSERT_LT(upper_block, m.blocks.size());
  const auto& blk = m.blocks[upper_block];
  solver::AliveMask alive(m.blocks.size());
  alive[upper_block].assign(blk.size(), 1);
  std::size_t corner_element = blk.size();  // the element over x, y in [0, 1] mm
  for (std::size_t e = 0; e < blk.size(); ++e) {
    double cx = 0, cy = 0;
    for (int k = 0; k < 8; ++k) {
      cx += m.X[3 * std::size_t(blk.conn[8 * e + k])] / 8;
      cy += m.X[3 * std::size_t(blk.conn[8 * e + k]) + 1] / 8;
    }
    if (cx < 1e-3 && cy < 1e-3) corner_element = e;
  }
  ASSERT_LT(corner_element, blk.size());
  alive[upper_block][corner_element] = 0;
  tiebreaks.on_erosion(alive, m.X);
  const auto& pairs = tiebreaks.pairs().at(0);
  std::size_t released = 0, corner_pair = itf.num_pairs();
  for (std::size_t p = 0; p < itf.num_pairs(); ++p) {
    if (pairs.released(p)) ++released;
    const double* X = &m.X[3 * std::size_t(itf.upper_nodes[p])];
    if (std::abs(X[0]) < 1e-9 && std::abs(X[1]) < 1e-9) corner_pair = p;
  }
  ASSERT_LT(corner_pair, itf.num_pairs());
  EXPECT_EQ(released, 1u) << "only the corner node's one element of ply 2 eroded";
  EXPECT_TRUE(pairs.released(corner_pair));
  EXPECT_EQ(pairs.damage()[corner_pair], 1.0);
  std::fill(alive[upper_block].begin(), alive[upper_block].end(), 0);
  tiebreaks.on_erosion(alive, m.X);
  released = 0;
  for (std::size_t p = 0; p < itf.num_pairs(); ++p) released += pairs.released(p) ? 1 : 0;
  EXPECT_EQ(released, itf.num_pairs()) << "ply 2 gone: every pair joins nothing";
}

TEST(InterfaceScene, MergedIsTheDefaultAndBondsThePairs) {
  for (const std::string form : {"angle-change", "{select: angle-change}", "{select: all, model: merged}"}) {
    const model::Model m = build(scene(form));
    ASSERT_FALSE(m.interfaces.empty()) << form;
    EXPECT_TRUE(m.interfaces_bonded);
    for (const auto& itf : m.interfaces) {
      EXPECT_FALSE(itf.tiebreak);
      for (Index n : itf.upper_nodes) EXPECT_EQ(m.mass[n], 0.0) << "upper duplicates are unused when merged";
    }
  }
}

TEST(InterfaceScene, PerInterfaceOverrideAndPrecrack) {
  const model::Model m = build(scene("{select: all, model: tiebreak, " + kLaw +
                                     ", per_interface: {2: {NFLS: 30 MPa, precrack: {x: [0, 1.5]}}}}"));
  ASSERT_EQ(m.interfaces.size(), 2u);
  EXPECT_DOUBLE_EQ(m.interfaces[0].tiebreak->law.NFLS, 60e6);
  EXPECT_FALSE(m.interfaces[0].tiebreak->has_precrack);
  EXPECT_DOUBLE_EQ(m.interfaces[1].tiebreak->law.NFLS, 30e6);
  EXPECT_DOUBLE_EQ(m.interfaces[1].tiebreak->law.SFLS, 50e6) << "keys not overridden stay";
  EXPECT_TRUE(m.interfaces[1].tiebreak->has_precrack);
  EXPECT_DOUBLE_EQ(m.interfaces[1].tiebreak->precrack_x[1], 1.5e-3);
}

void expect_error(const std::string& yaml, const std::vector<std::string>& parts) {
  const std::string e = error_of(yaml);
  for (const auto& p : parts) EXPECT_NE(e.find(p), std::string::npos) << "missing '" << p << "' in: " << e;
}

TEST(InterfaceScene, BadInputIsRefusedWithLocationAndKey) {
  // Missing NFLS: the law's own validation, prefixed with the interfaces map's location.
  expect_error(scene("{select: all, model: tiebreak, SFLS: 60 MPa, ERATEN: 765 J/m^2, ERATES: 1250 J/m^2, CN: 1e5}"),
               {"itf.yaml:16:15: laminate.interfaces (interface 1)", "NFLS is missing"});
  for (const char* key : {"NFLS", "SFLS", "ERATEN", "ERATES", "CN"}) {
    std::string law = kLaw;
    const auto at = law.find(std::string(key) + ": ");
    const auto end = law.find(',', at);
    law.replace(at, end - at, std::string(key) + ": -1");
    expect_error(scene("{select: all, model: tiebreak, " + law + "}"),
                 {"itf.yaml:16:", std::string("laminate.interfaces.") + key, "must be > 0"});
  }
  // Onset opening not below the final one, with the numbers.
  expect_error(scene("{select: all, model: tiebreak, OPTION: 9, NFLS: 60 MPa, SFLS: 60 MPa, ERATEN: 765 J/m^2, "
                     "ERATES: 1250 J/m^2, CN: 1 N/mm^3}"),
               {"(interface 1)", "mode I: the onset opening NFLS/CN = 0.06 m"});
  expect_error(scene("{select: all, model: tiebreak, " + kLaw + ", precrack: {x: [0, 5]}}"),
               {"laminate.interfaces.precrack.x", "inside the plate"});
  expect_error(scene("{select: [1], model: tiebreak, " + kLaw + ", per_interface: {2: {NFLS: 1}}}"),
               {"laminate.interfaces.per_interface", "interface 2 is not a delaminating interface"});
  expect_error(scene("{select: all, model: merged, NFLS: 60 MPa}"),
               {"laminate.interfaces.NFLS", "model: tiebreak"});
  expect_error(scene("{select: all, model: glue}"), {"laminate.interfaces.model"});
  // Interfaces outside a laminate.
  const std::string boxes =
      "units: SI\ncontrol: {termination_time: 1.0e-5}\n"
      "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210 GPa, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1}\nparts:\n  p: {id: 1, material: steel, section: s}\n"
      "mesh:\n  boxes:\n    - {part: p, origin: [0, 0, 0], size: [1, 1, 1], elements: [1, 1, 1]}\n"
      "interfaces: {select: all, model: tiebreak}\n";
  expect_error(boxes, {"itf.yaml:12:", "interfaces", "need a laminate"});
}

}  // namespace
}  // namespace plyimpact
