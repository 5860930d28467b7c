// The `model: cohesive` (*MAT_138) schema of the laminate's `interfaces:` and the model it builds:
//  - the card's keys reach the OPTION 9 law with their units converted (EN = CN, ET = CT2CN CN,
//    T = NFLS, S = SFLS, GIC = ERATEN, GIIC = ERATES, XMU = PARAM), T = 0 with UND gives 2 GIC / UND;
//  - the pairs stay apart; RO (mass per unit area) adds RO x interface area to the model, half on
//    each side, and nothing without RO;
//  - the interface contributor holds one cohesive element per interface segment, 4 points each,
//    whose point areas sum to the interface area; a pre-crack separates the points in its region; history columns and energies as the tiebreak's;
//  - bad input is refused with file:line:col, the key, the *MAT_138 field and the numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "interface/interface_tiebreaks.hpp"
#include "laminate_scene_support.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

std::string scene(const std::string& interfaces) {
  return "units: mm-t-s-MPa\n"
         "control: {termination_time: 1.0e-5}\n"
         "materials:\n"
         "  ply: {card: MAT_002, RO: 1600 kg/m^3, EA: 120 GPa, EB: 10 GPa, EC: 10 GPa, PRBA: 0.025, PRCA: 0.025,\n"
         "        PRCB: 0.45, GAB: 5 GPa, GBC: 3.5 GPa, GCA: 5 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
         "laminate:\n"
         "  length: 4\n  width: 2\n  ply_thickness: [0.5, 0.25, 0.25]\n  stacking: [0, 90, 90]\n"
         "  material: ply\n  section: s\n  element_size: 1\n"
         "  interfaces: " + interfaces + "\n";
}

const std::string kCard = "T: 60 MPa, S: 50 MPa, GIC: 765 J/m^2, GIIC: 1250 J/m^2, XMU: -2, EN: 100 kN/mm^3, "
                          "ET: 50 kN/mm^3";

// kCard with `key` set to `value` (replaced where kCard has it, appended otherwise).
std::string card_with(const std::string& key, const std::string& value) {
  std::string card = kCard;
  const auto at = card.find(key + ": ");
  if (at == std::string::npos) return card + ", " + key + ": " + value;
  const auto end = card.find(',', at);
  card.replace(at, (end == std::string::npos ? card.size() : end) - at, key + ": " + value);
  return card;
}

model::Model build(const std::string& yaml) { return test::build_laminate(yaml, "coh.yaml"); }

std::string error_of(const std::string& yaml) { return test::laminate_error(yaml, "coh.yaml"); }

void expect_error(const std::string& yaml, const std::vector<std::string>& parts) {
  const std::string e = error_of(yaml);
  for (const auto& p : parts) EXPECT_NE(e.find(p), std::string::npos) << "missing '" << p << "' in: " << e;
}

double total_mass(const model::Model& m) {
  double total = 0;
  for (double v : m.mass) total += v;
  return total;
}

TEST(CohesiveScene, CardReachesTheLawAndTheElements) {
  const model::Model m = build(scene("{select: angle-change, model: cohesive, " + kCard + "}"));
  ASSERT_EQ(m.interfaces.size(), 1u);
  const auto& itf = m.interfaces[0];
  ASSERT_TRUE(itf.tiebreak);
  EXPECT_EQ(itf.tiebreak->model, config::InterfaceLawSpec::Model::Cohesive);
  EXPECT_FALSE(m.interfaces_bonded) << "the pairs stay apart";
  const auto& law = itf.tiebreak->law;
  EXPECT_EQ(law.option, cohesive::TiebreakOption::MixedMode);
  EXPECT_DOUBLE_EQ(law.NFLS, 60e6);
  EXPECT_DOUBLE_EQ(law.SFLS, 50e6);
  EXPECT_DOUBLE_EQ(law.ERATEN, 765);
  EXPECT_DOUBLE_EQ(law.ERATES, 1250);
  EXPECT_DOUBLE_EQ(law.PARAM, -2);
  EXPECT_DOUBLE_EQ(law.CN, 1e14);
  EXPECT_DOUBLE_EQ(law.CT2CN, 0.5);
  EXPECT_NEAR(total_mass(m), 1600 * 4e-3 * 2e-3 * 1e-3, 1e-12) << "no RO: the elements are massless";

  solver::Solver solver(m);
  const interface::InterfaceTiebreaks* itfs = nullptr;
  for (const auto& c : solver.contributors())
    if (auto* p = dynamic_cast<const interface::InterfaceTiebreaks*>(c.get())) itfs = p;
  ASSERT_NE(itfs, nullptr);
  EXPECT_TRUE(itfs->pairs().empty());
  ASSERT_EQ(itfs->cohesive().size(), 1u);
  const auto& el = itfs->cohesive()[0];
  EXPECT_EQ(el.size(), 8u) << "4 x 2 segments of 1 mm";
  double area = 0;
  for (std::size_t p = 0; p < el.num_points(); ++p) area += el.point_area(p);
  EXPECT_NEAR(area, 8e-6, 1e-18);
  const auto cols = itfs->history_columns();
  ASSERT_EQ(cols.size(), 2u);
  EXPECT_EQ(cols[1], "delaminated_area_1");
  EXPECT_EQ(solver.balance().value("interface_elastic"), 0.0);
}

TEST(CohesiveScene, UltimateOpeningsAndAreaDensity) {
  const model::Model m = build(scene(
      "{select: angle-change, model: cohesive, T: 0, UND: 0.02 mm, S: 50 MPa, GIC: 765 J/m^2, GIIC: 1250 J/m^2, "
      "XMU: 1, EN: 100 kN/mm^3, ET: 100 kN/mm^3, RO: 0.5 kg/m^2, precrack: {x: [0, 1]}}"));
  const auto& spec = *m.interfaces[0].tiebreak;
  EXPECT_NEAR(spec.law.NFLS, 2 * 765 / 0.02e-3, 1e-6) << "T = 2 GIC / UND";
  EXPECT_NEAR(total_mass(m), 1600 * 4e-3 * 2e-3 * 1e-3 + 0.5 * 8e-6, 1e-15) << "RO x area";
  const auto& itf = m.interfaces[0];
  double lower = 0, upper = 0;
  for (std::size_t p = 0; p < itf.num_pairs(); ++p) {
    lower += m.mass[itf.lower_nodes[p]];
    upper += m.mass[itf.upper_nodes[p]];
  }
  // Lower nodes: a quarter of the 0.5 mm ply's mass plus half of RO A; upper: of the 0.25 mm ply.
  EXPECT_NEAR(lower - upper, 1600 * 8e-6 * (0.5e-3 - 0.25e-3) / 2, 1e-15) << "RO splits evenly";
  // Pre-crack x <= 1 mm: corner points (INTFAIL blank) at x = 0 and 1, a quarter of a 1 mm^2 segment
  // each: the pairs' 1.5 mm strip across the 2 mm width, 3 mm^2.
  const auto el = interface::make_interface_cohesive(m, itf);
  double separated = 0;
  for (std::size_t p = 0; p < el.num_points(); ++p)
    if (el.damage()[p] >= 1) separated += el.point_area(p);
  EXPECT_NEAR(separated, 3e-6, 1e-18);
}

TEST(CohesiveScene, BadInputIsRefusedWithLocationAndKey) {
  // Missing card fields: named as *MAT_138 spells them, at the interfaces map.
  expect_error(scene("{select: all, model: cohesive, S: 60 MPa, GIC: 765 J/m^2, GIIC: 1250 J/m^2, EN: 1e5}"),
               {"coh.yaml:16:15: laminate.interfaces (interface 1, *MAT_138)", "T is missing", "ET is missing",
                "XMU is missing"});
  for (const char* key : {"EN", "ET", "GIC", "GIIC", "UND"}) {
    expect_error(scene("{select: all, model: cohesive, " + card_with(key, "-1") + "}"),
                 {"coh.yaml:16:", std::string("laminate.interfaces.") + key, "must be > 0"});
  }
  // Snap-back, with the numbers and the card's names.
  expect_error(scene("{select: all, model: cohesive, T: 60 MPa, S: 60 MPa, GIC: 765 J/m^2, GIIC: 1250 J/m^2, "
                     "XMU: 1, EN: 1 N/mm^3, ET: 1 N/mm^3}"),
               {"(interface 1, *MAT_138)", "mode I: the onset opening T/EN = 0.06 m", "2 GIC/T = 2.55e-05 m",
                "mode II: the onset opening S/ET"});
  expect_error(scene("{select: all, model: cohesive, " + kCard + ", UND: 0.02 mm}"),
               {"UND is read only when T is 0 or blank"});
  expect_error(scene("{select: all, model: cohesive, " + card_with("XMU", "0") + "}"), {"XMU must be > 0"});
  expect_error(scene("{select: all, model: cohesive, " + kCard + ", NFLS: 60 MPa}"),
               {"laminate.interfaces.NFLS", "a tiebreak key with model: cohesive"});
  expect_error(scene("{select: all, model: tiebreak, OPTION: 9, NFLS: 60 MPa, SFLS: 60 MPa, ERATEN: 765 J/m^2, "
                     "ERATES: 1250 J/m^2, CN: 100 kN/mm^3, GIC: 765 J/m^2}"),
               {"laminate.interfaces.GIC", "a *MAT_138 key with model: tiebreak"});
  expect_error(scene("{select: all, model: cohesive, " + kCard + ", per_interface: {1: {CN: 1}}}"),
               {"laminate.interfaces.per_interface.1"});
}

}  // namespace
}  // namespace plyimpact
