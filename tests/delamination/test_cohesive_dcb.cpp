// The double cantilever beam of test_dcb.cpp run three times through the whole chain (scene, mesher,
// model builder, interface contributor, explicit solver): with tiebreak OPTION 9 pairs, and with
// *MAT_138 cohesive elements of the same constants (EN = CN, ET = CT2CN CN, T = NFLS, S = SFLS,
// GIC = ERATEN, GIIC = ERATES, XMU = PARAM) integrated at corner points and at Gauss points.
//
// Why they should agree: both apply the same point law (cohesive/traction_law.hpp) to the same
// opening field of the same mesh. The tiebreak integrates it at the nodes (each pair carries its
// tributary area), which is exactly what the element does with Newton-Cotes (corner) points, INTFAIL
// blank as LS-DYNA reads it: each corner point carries a quarter of its segment, the points of the
// segments around a node see that node's opening, and the interface is flat by the DCB's symmetry,
// so the frames agree. The two curves then agree to round-off, well inside the 2 %.
// With 2 x 2 Gauss points (INTFAIL > 0) the law is sampled between the nodes and the points of a
// segment couple its nodes. Before damage both interfaces are stiff ties (their compliance, NFLS/CN
// = 0.2 um at the peak against an arm opening of 1.2 mm, is negligible), so with the same nodes free
// the elastic branches agree. Once the cohesive zone (about 4 segments) forms, the Gauss points
// near the tip see the opening interpolated from two nodes, the tip node can open further while its
// neighbour closes (Schellekens & de Borst 1993 on the traction oscillations of Gauss-integrated
// stiff interfaces), and damage starts earlier: a lower peak and a different propagation branch at
// this mesh. That difference is printed and documented, not asserted. We compare the loads at the
// tiebreak's openings, relative to its peak, from 20 % of the peak on the rising branch on.
//
// Also: the cohesive runs' energy ratio stays within 1 +- 0.01 through the propagation (as in
// test_dcb.cpp: from the moment the external work reaches 5 % of the strain energy at the critical
// opening); the delaminated area grows; a restart through visit_state continues bit for bit.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "core/state_io.hpp"
#include "dcb_beam.hpp"

namespace plyimpact {
namespace {

using namespace dcb;

constexpr double kEnd = 2.0e-3;  // s: an opening of 2.3 mm, the crack grown by about 10 mm

const char* kTiebreak =
    "{select: [1], model: tiebreak, OPTION: 9, NFLS: 20 MPa, SFLS: 20 MPa, ERATEN: 200 J/m^2,\n"
    "               ERATES: 400 J/m^2, PARAM: 1, CN: 100 kN/mm^3, CT2CN: 1, precrack: {x: [0, 25]}}";
// INTFAIL blank (0): Newton-Cotes points, LS-DYNA's reading of a blank field; INTFAIL 1: 2 x 2 Gauss.
const char* kCohesive =
    "{select: [1], model: cohesive, T: 20 MPa, S: 20 MPa, GIC: 200 J/m^2, GIIC: 400 J/m^2,\n"
    "               XMU: 1, EN: 100 kN/mm^3, ET: 100 kN/mm^3, precrack: {x: [0, 25]}}";
// Gauss points with the pre-crack reaching past the segment [25, 26] mm's points (25.21, 25.79): then the
// same nodes are free as with the pairs (x <= 25 mm). With the pairs' region, x <= 25 mm, the points
// of that segment stay bonded and tie the node at 25 mm through the segment's interpolation: a crack
// one node shorter (docs/delamination.md gives the figures of that run).
const char* kCohesiveGauss =
    "{select: [1], model: cohesive, T: 20 MPa, S: 20 MPa, GIC: 200 J/m^2, GIIC: 400 J/m^2,\n"
    "               XMU: 1, EN: 100 kN/mm^3, ET: 100 kN/mm^3, INTFAIL: 1, precrack: {x: [0, 25.8]}}";

struct DcbRun {
  Curve curve;
  double max_ratio_err = 0;
  double precrack_area = 0, final_area = 0, dissipated = 0;
  long cycles = 0;
  double wall = 0;
};

DcbRun run_dcb(const char* interfaces) {
  const config::Scene scene = config::load_scene_from_string(dcb_scene(interfaces, kEnd), "dcb.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  solver::Solver solver(model);
  DcbRun c;
  c.precrack_area = interfaces_of(solver)->delaminated_area();
  // The ratio is judged once the external work reaches 5 % of the strain energy 1/2 P_c delta_c at the
  // critical opening (corrected beam theory with the pre-crack a0 = 25 mm, as test_dcb.cpp).
  const Record r = record_run(solver, model, kEnd, 0.05 * 0.5 * critical_load(a0) * critical_opening(a0));
  c.curve = smoothed(r);
  c.max_ratio_err = r.max_ratio_err;
  c.final_area = interfaces_of(solver)->delaminated_area();
  c.dissipated = solver.balance().value("interface_dissipated");
  c.cycles = r.cycles;
  c.wall = r.wall;
  return c;
}

void print(const char* name, const DcbRun& r) {
  const Curve& c = r.curve;
  double at = 0;
  const double peak = peak_of(c, &at);
  std::printf("%-28s %ld cycles, %.2f s; peak %.5g N at %.4g mm; final %.5g N at %.4g mm; delaminated %.4g mm^2 "
              "(pre-crack %.4g); dissipated %.4g mJ; max |ratio - 1| %.2e\n",
              name, r.cycles, r.wall, peak, at * 1e3, c.load.back(), c.opening.back() * 1e3, r.final_area * 1e6,
              r.precrack_area * 1e6, r.dissipated * 1e3, r.max_ratio_err);
}

TEST(CohesiveDCB, Option9AndMat138AgreeOnTheLoadOpeningCurve) {
  const DcbRun tb_run = run_dcb(kTiebreak), nc_run = run_dcb(kCohesive), ga_run = run_dcb(kCohesiveGauss);
  print("tiebreak OPTION 9:", tb_run);
  print("*MAT_138 Newton-Cotes:", nc_run);
  print("*MAT_138 2x2 Gauss:", ga_run);
  const Curve &tb = tb_run.curve, &nc = nc_run.curve, &ga = ga_run.curve;
  const double end = tb.opening.back();
  const Difference d_nc = difference(tb, nc, end), d_ga = difference(tb, ga, end);
  // The elastic branch: up to 40 % of the peak load no point of the interface is damaged yet.
  double elastic_end = 0;
  for (std::size_t i = 0; i < tb.load.size() && tb.load[i] < 0.4 * peak_of(tb); ++i) elastic_end = tb.opening[i];
  const Difference e_ga = difference(tb, ga, elastic_end);
  std::printf("load difference from the tiebreak / its peak: Newton-Cotes max %.2f %% at %.4g mm, rms %.2f %%; "
              "Gauss max %.2f %% at %.4g mm, rms %.2f %%, elastic branch (to %.3g mm) max %.2f %%; peaks %+.2f %% "
              "and %+.2f %%\n",
              100 * d_nc.max, d_nc.at * 1e3, 100 * d_nc.rms, 100 * d_ga.max, d_ga.at * 1e3, 100 * d_ga.rms,
              elastic_end * 1e3, 100 * e_ga.max, 100 * (peak_of(nc) / peak_of(tb) - 1),
              100 * (peak_of(ga) / peak_of(tb) - 1));

  EXPECT_LT(d_nc.max, 0.02) << "the issue's 2 % on the load-opening curve (same quadrature as the pairs)";
  // Gauss points: before any damage both interfaces are stiff ties on the same free nodes (their
  // own compliance below 0.1 % of the arms'), so the elastic branches agree to 1 %; beyond, the Gauss
  // rule's tip behaviour differs (header; measured and reported, not asserted).
  EXPECT_LT(e_ga.max, 0.01) << "elastic branch with Gauss points";
  for (const DcbRun* c : {&nc_run, &ga_run}) {
    EXPECT_LT(c->max_ratio_err, 0.01);
    EXPECT_GT(c->final_area, c->precrack_area + 5 * 2e-3 * 1e-3) << "the crack grew by several segments";
  }
  // Pre-crack: the points in the region start separated. Corner points are the pairs' nodes (25.5 mm
  // of strips); the Gauss points of the segments up to x = 26 mm lie in x <= 25.8 mm.
  EXPECT_NEAR(nc_run.precrack_area, tb_run.precrack_area, 1e-12);
  EXPECT_NEAR(ga_run.precrack_area, 26e-3 * 2e-3, 1e-12);
  // Every point that separated dissipated its G_c (pure mode I here: GIC = 200 J/m^2; points still
  // softening add more), so the dissipation is at least GIC times the grown area.
  for (const DcbRun* c : {&tb_run, &nc_run, &ga_run})
    EXPECT_GE(c->dissipated, GIc * (c->final_area - c->precrack_area) * (1 - 1e-6));
}

// Restart through the propagation with *MAT_138 elements: the per-point history and the dissipated
// energy are run state; a run written after the damage zone formed and read into a fresh solver
// continues bit for bit as the uninterrupted one.
TEST(CohesiveDCB, RestartDuringPropagationIsBitIdentical) {
  const config::Scene scene = config::load_scene_from_string(dcb_scene(kCohesiveGauss, kEnd), "dcb.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  const auto damaged = [](const solver::Solver& s) {
    std::size_t n = 0;
    for (double d : interfaces_of(s)->cohesive()[0].damage()) n += d > 0 && d < 1;
    return n;
  };
  solver::Solver a(model);
  while (a.state().time < 1.0e-3) a.step();  // opening ~1 mm: a damage zone at the tip
  ASSERT_GT(damaged(a), 0u);
  std::stringstream file;
  StateWriter writer(file);
  a.visit_state(writer);
  solver::Solver b(model);
  StateReader reader(file, "memory");
  b.visit_state(reader);
  for (int i = 0; i < 1000; ++i) {
    a.step();
    b.step();
  }
  StateDigest da, db;
  a.visit_state(da);
  b.visit_state(db);
  EXPECT_EQ(da.value(), db.value());
  EXPECT_EQ(a.balance().value("interface_dissipated"), b.balance().value("interface_dissipated"));
  EXPECT_GT(a.balance().value("interface_dissipated"), 0.0);
}

}  // namespace
}  // namespace plyimpact
