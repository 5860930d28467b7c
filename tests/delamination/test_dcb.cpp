// Double cantilever beam (mode I) through the whole chain: laminate scene with one tiebreak
// interface (OPTION 9) and a pre-crack, model builder (pairs kept apart), interface contributor,
// explicit solver. Two unidirectional arms of thickness h (2 elements each, ELFORM 1 with IHQ 6,
// whose assumed-strain hourglass control gives the elastic bending stiffness on coarse meshes),
// width b, pre-crack a0 from the loaded end; the arm ends (x = 0) are pulled apart in z with
// prescribed velocities that ramp up smoothly (1 - cos over several periods of the arms' first
// bending mode, so the response is quasi-static), then stay constant.
//
// Independent answers (corrected beam theory: J. G. Williams, "End corrections for orthotropic DCB specimens",
// Compos. Sci. Technol. 35 (1989) 367-376; ASTM D5528):
//   compliance  C = delta / P = 8 (a + Delta)^3 / (E11 b h^3),
//               Delta = chi h, chi = sqrt(E11 / (11 G13) (3 - 2 (Gamma / (1 + Gamma))^2)),
//               Gamma = 1.18 sqrt(E11 E22) / G13 (root rotation of the arms);
//   G_I = P^2 / (2 b) dC/da = 12 P^2 (a + Delta)^2 / (E11 b^2 h^3), so the load at which the
//               pre-crack propagates is P_c = b / (a0 + Delta) sqrt(E11 h^3 G_Ic / 12);
//   propagation branch (G_I = G_Ic, eliminate a + Delta): P(delta) = sqrt(8 b^2 (E11 h^3 G_Ic / 12)^(3/2) / (E11 h^3 delta)).
// Tolerances:
//   - compliance 5 %: beam theory with the Williams correction agrees with 2-D elasticity to ~2 %;
//     two one-point elements through each arm with IHQ 6 reproduce pure bending (docs/theory.md),
//     and the interface's own compliance 1/CN is below 0.1 % of the arms' (opening NFLS/CN = 0.2 um
//     at the peak against delta_c = 1.24 mm);
//   - peak load and the propagation branch 10 %: the cohesive zone (Turon et al. 2007 length
//     l_cz = 9 pi / 32 E22 G_Ic / NFLS^2 = 4.4 mm, about 4 segments of this CI mesh) replaces the
//     LEFM crack tip with a zone whose effective tip lies ahead of the damage front, and with 1 mm
//     segments the damage front advances in jumps of one segment (a 1 mm jump in a = 25 mm moves
//     P by 1 / 27.6 = 3.6 %); the load is also sampled with the arms' residual vibration.
//   - energy balance: |total - external work| <= 1 % of the external work from the moment the work
//     reaches 5 % of the strain energy at delta_c (before, both are round-off sized), through
//     propagation; interface energies >= 0.
// CN is the seed's 100 kN/mm^3 (Table 8.6): on this mesh its pair step (~9e-8 s) is close to the
// element step, so the combined step costs about a third more cycles, which the CI size affords.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/state_io.hpp"
#include "dcb_beam.hpp"

namespace plyimpact {
namespace {

using namespace dcb;

// s: the opening 2 V (kEnd - kRamp / 2) = 3.1 mm at the end is 2.5 times the critical opening
// delta_c = 8 (a0 + Delta)^2 sqrt(G_Ic / (12 E11 h^3)) = 1.24 mm (the crack front then near
// a + Delta = 44 mm, as delta grows with (a + Delta)^2 on the propagation branch).
constexpr double kEnd = 2.5e-3;

const char* kInterfaces =
    "{select: [1], model: tiebreak, OPTION: 9, NFLS: 20 MPa, SFLS: 20 MPa, ERATEN: 200 J/m^2,\n"
    "               ERATES: 400 J/m^2, PARAM: 1, CN: 100 kN/mm^3, CT2CN: 1, precrack: {x: [0, 25]}}";

std::string dcb_scene() { return dcb::dcb_scene(kInterfaces, kEnd); }

TEST(DCB, ComplianceCriticalLoadPropagationAndEnergy) {
  const config::Scene scene = config::load_scene_from_string(dcb_scene(), "dcb.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  ASSERT_EQ(model.interfaces.size(), 1u);
  ASSERT_TRUE(model.interfaces[0].tiebreak);

  solver::Solver solver(model);
  const interface::InterfaceTiebreaks* itf = nullptr;
  for (const auto& c : solver.contributors())
    if (auto* p = dynamic_cast<const interface::InterfaceTiebreaks*>(c.get())) itf = p;
  ASSERT_NE(itf, nullptr);
  const double precrack_area = itf->pairs()[0].size() ? [&] {
    double a = 0;
    for (std::size_t p = 0; p < itf->pairs()[0].size(); ++p)
      if (itf->pairs()[0].damage()[p] >= 1) a += itf->pairs()[0].area(p);
    return a;
  }() : 0.0;
  EXPECT_NEAR(precrack_area, a0 * b, 0.5e-3 * b) << "pre-crack: the pairs up to x = a0 (the last row carries half a segment)";

  // Sets in constraint order: tip_top first.
  const auto& tops = model.node_sets[model.constrained_sets[0]];
  ASSERT_EQ(tops.name, "tip_top");

  // The cracked length is where the traction-free region ends: the separated pairs' area over b
  // (the pairs at x = a0 are free too, their tributary strip reaches half a segment further).
  const double a_eff = precrack_area / b;
  const double delta_w = williams_delta();
  const double c_theory = compliance(a_eff);
  const double p_c = critical_load(a_eff);
  const double delta_c = c_theory * p_c;
  const Record rec = record_run(solver, model, kEnd, 0.05 * 0.5 * p_c * delta_c);
  const double max_ratio_err = rec.max_ratio_err, min_elastic = rec.min_elastic, min_dissipated = rec.min_dissipated;
  const Curve curve = smoothed(rec);
  const std::vector<double>&d_s = curve.opening, &p_s = curve.load;
  double peak = 0, peak_opening = 0, sxx = 0, sxy = 0;  // least squares delta = C P over 0.2 .. 0.6 P_c
  for (std::size_t i = 0; i < p_s.size(); ++i) {
    if (p_s[i] > 0.2 * p_c && p_s[i] < 0.6 * p_c && peak < 0.6 * p_c) {
      sxx += p_s[i] * p_s[i];
      sxy += p_s[i] * d_s[i];
    }
    if (p_s[i] > peak) {
      peak = p_s[i];
      peak_opening = d_s[i];
    }
  }
  const double last_p = p_s.back(), last_delta = d_s.back();
  const double wall = rec.wall;
  const double c_fe = sxy / sxx;
  const double area = itf->delaminated_area();
  std::printf("DCB: %zu elements, %ld cycles, wall %.2f s; Delta (Williams) %.3f mm\n", model.num_elements(),
              solver.state().cycle, wall, delta_w * 1e3);
  std::printf("  compliance %.5g m/N, beam theory %.5g m/N, error %+.2f %%\n", c_fe, c_theory,
              100 * (c_fe / c_theory - 1));
  std::printf("  peak load %.5g N at opening %.4g mm, LEFM P_c %.5g N, error %+.2f %%\n", peak, peak_opening * 1e3,
              p_c, 100 * (peak / p_c - 1));
  std::printf("  final load %.5g N at opening %.4g mm, propagation branch %.5g N, error %+.2f %%\n", last_p,
              last_delta * 1e3, propagation_load(last_delta), 100 * (last_p / propagation_load(last_delta) - 1));
  std::printf("  delaminated %.4g mm^2 (pre-crack %.4g), dissipated %.4g mJ, G_Ic x growth %.4g mJ; max |ratio - 1| %.2e\n",
              area * 1e6, precrack_area * 1e6, solver.balance().value("interface_dissipated") * 1e3,
              GIc * (area - precrack_area) * 1e3, max_ratio_err);

  // Dissipation: each separated pair dissipated G_Ic per area (pure mode I); partly damaged pairs
  // less than their critical energy (at most ERATES = 400 J/m^2 should a pair see shear).
  double damaged_area = 0;
  for (std::size_t p = 0; p < itf->pairs()[0].size(); ++p)
    if (itf->pairs()[0].damage()[p] > 0) damaged_area += itf->pairs()[0].area(p);
  const double dissipated = solver.balance().value("interface_dissipated");
  EXPECT_GE(dissipated, GIc * (area - precrack_area) * (1 - 1e-6));
  EXPECT_LE(dissipated, 400.0 * (damaged_area - precrack_area));

  EXPECT_NEAR(c_fe / c_theory, 1.0, 0.05);
  EXPECT_NEAR(peak / p_c, 1.0, 0.10);
  EXPECT_GT(area, precrack_area + 5 * b * 1e-3) << "the crack grew by several segments";
  EXPECT_NEAR(last_p / propagation_load(last_delta), 1.0, 0.10);
  EXPECT_LT(max_ratio_err, 0.01);
  EXPECT_GE(min_elastic, 0.0);
  EXPECT_GE(min_dissipated, 0.0);
}

// Restart through the propagation: the interfaces' history (damage, largest opening, slips, the
// dissipated energy, normals) is run state. A run written after the crack started to grow and read
// into a fresh solver continues bit for bit as the uninterrupted run (same state digest).
TEST(DCB, RestartDuringPropagationIsBitIdentical) {
  const config::Scene scene = config::load_scene_from_string(dcb_scene(), "dcb.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  const auto damaged = [](const solver::Solver& s) {
    for (const auto& c : s.contributors())
      if (auto* p = dynamic_cast<const interface::InterfaceTiebreaks*>(c.get())) {
        std::size_t n = 0;
        for (double d : p->pairs()[0].damage()) n += d > 0 && d < 1;
        return n;
      }
    return std::size_t(0);
  };
  solver::Solver a(model);
  while (a.state().time < 1.3e-3) a.step();  // past the critical opening: a damage zone exists
  ASSERT_GT(damaged(a), 0u);
  std::stringstream file;
  StateWriter writer(file);
  a.visit_state(writer);
  solver::Solver b(model);
  StateReader reader(file, "memory");
  b.visit_state(reader);
  for (int i = 0; i < 2000; ++i) {
    a.step();
    b.step();
  }
  StateDigest da, db;
  a.visit_state(da);
  b.visit_state(db);
  EXPECT_EQ(da.value(), db.value());
  EXPECT_EQ(a.balance().value("interface_dissipated"), b.balance().value("interface_dissipated"));
}

}  // namespace
}  // namespace plyimpact
