// A tiebreak contact between two parts whose meshes do not match, through the whole chain (scene,
// model, contributor, explicit solver): two stacked 4 x 4 x 1 mm steel blocks, the lower meshed
// 4 x 4, the upper 3 x 3 in plane, glued by `type: tiebreak_surface_to_surface` (OPTION 9) and pulled
// apart in mode I by a prescribed velocity on the upper block's top face.
// Independent answers:
//   - tying: every node of the upper block's bottom face is tied (16 of 16), the tied area is the
//     whole 16 mm^2 (the tributary areas of the slave faces);
//   - complete separation dissipates G_Ic A (A = 16 mm^2). Tolerance 1 %: the law dissipates exactly
//     G_c along a fixed direction (docs/delamination.md), and the only departure from pure mode I is
//     the shear opening from the blocks' Poisson contraction, 0.3 x 20 MPa / 210 GPa x 2 mm = 0.06 um
//     against a final opening of 20 um: a mode mixity below 1e-4, which moves G_c by less than 0.1 %;
//     the rest of the margin is for the few ties that unload and reload while the blocks vibrate;
//   - the energy balance (kinetic + internal + interface + dissipated = external work of the
//     prescribed motion) within 1 % from the moment the work reaches 5 % of G_Ic A;
//   - the whole area ends delaminated, and both interface energies stay >= 0.
// Bad input: a tiebreak key on an ordinary contact, and a rigid side, are refused at the key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "interface/surface_tiebreaks.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/contributors.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

constexpr double kGIc = 200;          // J/m^2
constexpr double kArea = 16e-6;       // m^2
constexpr double kRamp = 20e-6, kEnd = 0.3e-3;  // s
constexpr double kPull = 0.1;         // m/s: 30 um by the end, beyond the final opening 2 G / NFLS = 20 um

std::string scene(const std::string& contact_extra = "", const std::string& type = "tiebreak_surface_to_surface") {
  std::ostringstream y;
  y << "units: mm-t-s-MPa\n"
       "control: {termination_time: " << kEnd << "}\n"
       "materials:\n"
       "  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}\n"
       "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
       "parts:\n  lower: {material: steel, section: s}\n  upper: {material: steel, section: s}\n"
       "mesh:\n  merge_nodes: false\n  boxes:\n"
       "    - {part: lower, origin: [0, 0, 0], size: [4, 4, 1], elements: [4, 4, 1]}\n"
       "    - {part: upper, origin: [0, 0, 1], size: [4, 4, 1], elements: [3, 3, 1]}\n"
       "node_sets:\n  base: {plane: {axis: z, value: 0}}\n  top: {plane: {axis: z, value: 2}}\n"
       "boundary_conditions:\n  - {node_set: base, fix: [x, y, z]}\n"
       "  - {node_set: top, velocity: {dofs: [z], curve: [";
  for (int i = 0; i <= 16; ++i) {
    const double t = kRamp * i / 16;
    y << "[" << t << " s, " << kPull * 0.5 * (1 - std::cos(std::numbers::pi * t / kRamp)) << " m/s], ";
  }
  y << "[" << kEnd << " s, " << kPull << " m/s]]}}\n"
       "contacts:\n"
       "  - {name: glue, type: " << type << ", surfaces: [upper, lower], OPTION: 9, NFLS: 20 MPa, SFLS: 20 MPa,\n"
       "     ERATEN: 200 J/m^2, ERATES: 400 J/m^2, PARAM: 1, CN: 10 kN/mm^3, CT2CN: 1" << contact_extra << "}\n";
  return y.str();
}

TEST(TiebreakContactScene, NonMatchingBlocksTieSeparateAndDissipateGIc) {
  const config::Scene s = config::load_scene_from_string(scene(), "glue.yaml");
  const model::Model model = model::build_model(s, mesh::mesh_scene(s));
  ASSERT_EQ(model.tiebreak_contacts.size(), 1u);
  EXPECT_TRUE(model.contacts.empty());

  const interface::ContactTying tying = interface::tie_contact(model, model.tiebreak_contacts[0]);
  EXPECT_EQ(tying.result.ties.size(), 16u);
  EXPECT_EQ(tying.result.slave_nodes, 16u);
  double tied = 0;
  for (const auto& t : tying.result.ties) tied += t.area;
  EXPECT_NEAR(tied, kArea, 1e-9 * kArea);

  bool listed = false;
  for (const auto& sub : solver::subsystems(model))
    if (sub.name == "tiebreak_contacts") {
      listed = sub.active;
      EXPECT_NE(sub.detail.find("16 of 16 slave nodes tied"), std::string::npos) << sub.detail;
    }
  EXPECT_TRUE(listed);

  solver::Solver solver(model);
  double max_err = 0, min_elastic = 0, min_dissipated = 0;
  while (solver.state().time < kEnd * (1 - 1e-12)) {
    solver.step();
    if (solver.balance().external_work() > 0.05 * kGIc * kArea)
      max_err = std::max(max_err, std::abs(solver.energy_ratio() - 1));
    min_elastic = std::min(min_elastic, solver.balance().value("tiebreak_elastic"));
    min_dissipated = std::min(min_dissipated, solver.balance().value("tiebreak_dissipated"));
  }
  const double dissipated = solver.balance().value("tiebreak_dissipated");
  const interface::SurfaceTiebreaks* ties = nullptr;
  for (const auto& c : solver.contributors())
    if (auto* p = dynamic_cast<const interface::SurfaceTiebreaks*>(c.get())) ties = p;
  ASSERT_NE(ties, nullptr);
  std::printf("tiebreak contact: %ld cycles, dissipated %.5g J (G_Ic A %.5g J, %+.3f %%), delaminated %.4g mm^2, "
              "max |ratio - 1| %.2e\n",
              solver.state().cycle, dissipated, kGIc * kArea, 100 * (dissipated / (kGIc * kArea) - 1),
              ties->contacts()[0].separated_area() * 1e6, max_err);
  EXPECT_NEAR(ties->contacts()[0].separated_area(), kArea, 1e-9 * kArea);
  EXPECT_NEAR(dissipated, kGIc * kArea, 0.01 * kGIc * kArea);
  EXPECT_LT(max_err, 0.01);
  EXPECT_GE(min_elastic, 0.0);
  EXPECT_GE(min_dissipated, 0.0);
}

TEST(TiebreakContactScene, RefusesTiebreakKeysOnOrdinaryContactsAndRigidSides) {
  try {
    config::load_scene_from_string(scene("", "automatic_surface_to_surface"), "glue.yaml");
    FAIL() << "accepted a tiebreak law on an ordinary contact";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("glue.yaml:"), std::string::npos) << m;
    EXPECT_NE(m.find("a tiebreak field on a contact without a tiebreak"), std::string::npos) << m;
  }
  try {
    config::load_scene_from_string(scene(", SST: -1"), "glue.yaml");
    FAIL() << "accepted a negative contact thickness";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("glue.yaml:"), std::string::npos) << m;
    EXPECT_NE(m.find("SST"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace plyimpact
