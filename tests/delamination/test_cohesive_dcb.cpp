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

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "core/state_io.hpp"
#include "interface/interface_tiebreaks.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

constexpr double kRamp = 0.6e-3, kEnd = 2.0e-3;  // s
constexpr double kOpeningRate = 0.7;              // m/s per arm (test_dcb.cpp says why)
constexpr double kWindow = 0.1e-3;                // s, load averaging window (test_dcb.cpp)

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

std::string dcb_scene(const char* interfaces) {
  std::ostringstream y;
  y << "units: mm-t-s-MPa\n"
       "control: {termination_time: " << kEnd << "}\n"
       "materials:\n"
       "  ud:\n"
       "    card: MAT_002\n"
       "    RO: 1500 kg/m^3\n"
       "    EA: 120 GPa\n    EB: 10 GPa\n    EC: 10 GPa\n"
       "    PRBA: 0.025\n    PRCA: 0.025\n    PRCB: 0.45\n"
       "    GAB: 5 GPa\n    GBC: 3.5 GPa\n    GCA: 5 GPa\n"
       "    AOPT: 2\n    A: [1, 0, 0]\n    D: [0, 1, 0]\n"
       "sections:\n  arm: {ELFORM: 1, IHQ: 6, QM: 1}\n"
       "laminate:\n"
       "  length: 60\n  width: 2\n  ply_thickness: 1.5\n  stacking: [0, 0]\n"
       "  material: ud\n  section: arm\n  elements_per_ply: 2\n  element_size: 1\n"
       "  interfaces: " << interfaces << "\n"
       "node_sets:\n"
       "  tip_top: {box: {min: [-0.01, -1, 1.6], max: [0.01, 3, 3.1]}}\n"
       "  tip_bottom: {box: {min: [-0.01, -1, -0.1], max: [0.01, 3, 1.4]}}\n"
       "boundary_conditions:\n";
  for (int side = 0; side < 2; ++side) {
    y << "  - {node_set: " << (side == 0 ? "tip_top" : "tip_bottom") << ", velocity: {dofs: [z], curve: [";
    const double sign = side == 0 ? 1 : -1;
    for (int i = 0; i <= 24; ++i) {
      const double t = kRamp * i / 24;
      y << "[" << t << " s, " << sign * kOpeningRate * 0.5 * (1 - std::cos(std::numbers::pi * t / kRamp)) << " m/s], ";
    }
    y << "[" << kEnd << " s, " << sign * kOpeningRate << " m/s]]}}\n";
  }
  return y.str();
}

// Corrected beam theory of the arms (test_dcb.cpp: Williams 1989, ASTM D5528) for the pre-crack.
constexpr double E11 = 120e9, E22 = 10e9, G13 = 5e9, h = 1.5e-3, b = 2e-3, a0 = 25e-3, GIc = 200;
double williams_delta() {
  const double gamma = 1.18 * std::sqrt(E11 * E22) / G13;
  const double r = gamma / (1 + gamma);
  return h * std::sqrt(E11 / (11 * G13) * (3 - 2 * r * r));
}
double critical_load() { return b / (a0 + williams_delta()) * std::sqrt(E11 * h * h * h * GIc / 12); }
double critical_opening() { return 8 * std::pow(a0 + williams_delta(), 3) / (E11 * b * h * h * h) * critical_load(); }

const interface::InterfaceTiebreaks* interfaces_of(const solver::Solver& s) {
  for (const auto& c : s.contributors())
    if (auto* p = dynamic_cast<const interface::InterfaceTiebreaks*>(c.get())) return p;
  return nullptr;
}

struct Curve {
  std::vector<double> opening, load;  // m, N (window means)
  double max_ratio_err = 0;           // |energy ratio - 1| once the work is significant
  double precrack_area = 0, final_area = 0, dissipated = 0;
  long cycles = 0;
  double wall = 0;
};

Curve run_dcb(const char* interfaces) {
  const auto start = std::chrono::steady_clock::now();
  const config::Scene scene = config::load_scene_from_string(dcb_scene(interfaces), "dcb.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  solver::Solver solver(model);
  Curve c;
  c.precrack_area = interfaces_of(solver)->delaminated_area();
  const auto& tops = model.node_sets[model.constrained_sets[0]];
  // The ratio is judged once the external work reaches 5 % of the strain energy 1/2 P_c delta_c at the
  // critical opening (corrected beam theory with the pre-crack a0 = 25 mm, as test_dcb.cpp).
  const double work_threshold = 0.05 * 0.5 * critical_load() * critical_opening();
  std::vector<double> times, openings, loads;
  double opening = 0;
  while (solver.state().time < kEnd * (1 - 1e-12)) {
    const double dt = solver.state().dt_next_half;
    solver.step();
    const auto& s = solver.state();
    opening += 2 * s.v[3 * std::size_t(tops.nodes[0]) + 2] * dt;
    times.push_back(s.time);
    openings.push_back(opening);
    loads.push_back(std::abs(s.reaction[2]));
    if (solver.balance().external_work() > work_threshold)
      c.max_ratio_err = std::max(c.max_ratio_err, std::abs(solver.energy_ratio() - 1));
  }
  std::size_t lo = 0, hi = 0;
  double sum = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] - kWindow / 2 < 0 || times[i] + kWindow / 2 > times.back()) continue;
    while (hi < times.size() && times[hi] <= times[i] + kWindow / 2) sum += loads[hi++];
    while (times[lo] < times[i] - kWindow / 2) sum -= loads[lo++];
    c.opening.push_back(openings[i]);
    c.load.push_back(sum / double(hi - lo));
  }
  c.final_area = interfaces_of(solver)->delaminated_area();
  c.dissipated = solver.balance().value("interface_dissipated");
  c.cycles = solver.state().cycle;
  c.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

// Load of `c` at `opening` (linear interpolation; the openings increase monotonically).
double load_at(const Curve& c, double opening) {
  const auto it = std::lower_bound(c.opening.begin(), c.opening.end(), opening);
  if (it == c.opening.begin()) return c.load.front();
  if (it == c.opening.end()) return c.load.back();
  const std::size_t k = std::size_t(it - c.opening.begin());
  const double w = (opening - c.opening[k - 1]) / (c.opening[k] - c.opening[k - 1]);
  return c.load[k - 1] + w * (c.load[k] - c.load[k - 1]);
}

double peak_of(const Curve& c, double* at = nullptr) {
  double peak = 0;
  for (std::size_t i = 0; i < c.load.size(); ++i)
    if (c.load[i] > peak) {
      peak = c.load[i];
      if (at) *at = c.opening[i];
    }
  return peak;
}

// Largest and rms difference of `other` from `ref` at ref's openings up to `until`, relative to ref's
// peak load, from 20 % of that peak on the rising branch.
struct Difference {
  double max = 0, rms = 0, at = 0;
};
Difference difference(const Curve& ref, const Curve& other, double until) {
  const double peak = peak_of(ref);
  Difference d;
  std::size_t n = 0;
  bool rising = false;
  for (std::size_t i = 0; i < ref.load.size(); ++i) {
    if (ref.load[i] > 0.2 * peak) rising = true;
    if (!rising || ref.opening[i] > std::min(until, other.opening.back())) continue;
    const double diff = std::abs(load_at(other, ref.opening[i]) - ref.load[i]) / peak;
    d.rms += diff * diff;
    ++n;
    if (diff > d.max) {
      d.max = diff;
      d.at = ref.opening[i];
    }
  }
  d.rms = std::sqrt(d.rms / double(std::max<std::size_t>(n, 1)));
  return d;
}

void print(const char* name, const Curve& c) {
  double at = 0;
  const double peak = peak_of(c, &at);
  std::printf("%-28s %ld cycles, %.2f s; peak %.5g N at %.4g mm; final %.5g N at %.4g mm; delaminated %.4g mm^2 "
              "(pre-crack %.4g); dissipated %.4g mJ; max |ratio - 1| %.2e\n",
              name, c.cycles, c.wall, peak, at * 1e3, c.load.back(), c.opening.back() * 1e3, c.final_area * 1e6,
              c.precrack_area * 1e6, c.dissipated * 1e3, c.max_ratio_err);
}

TEST(CohesiveDCB, Option9AndMat138AgreeOnTheLoadOpeningCurve) {
  const Curve tb = run_dcb(kTiebreak);
  const Curve nc = run_dcb(kCohesive);
  const Curve ga = run_dcb(kCohesiveGauss);
  print("tiebreak OPTION 9:", tb);
  print("*MAT_138 Newton-Cotes:", nc);
  print("*MAT_138 2x2 Gauss:", ga);
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
  for (const Curve* c : {&nc, &ga}) {
    EXPECT_LT(c->max_ratio_err, 0.01);
    EXPECT_GT(c->final_area, c->precrack_area + 5 * 2e-3 * 1e-3) << "the crack grew by several segments";
  }
  // Pre-crack: the points in the region start separated. Corner points are the pairs' nodes (25.5 mm
  // of strips); the Gauss points of the segments up to x = 26 mm lie in x <= 25.8 mm.
  EXPECT_NEAR(nc.precrack_area, tb.precrack_area, 1e-12);
  EXPECT_NEAR(ga.precrack_area, 26e-3 * 2e-3, 1e-12);
  // Every point that separated dissipated its G_c (pure mode I here: GIC = 200 J/m^2; points still
  // softening add more), so the dissipation is at least GIC times the grown area.
  for (const Curve* c : {&tb, &nc, &ga})
    EXPECT_GE(c->dissipated, GIc * (c->final_area - c->precrack_area) * (1 - 1e-6));
}

// Restart through the propagation with *MAT_138 elements: the per-point history and the dissipated
// energy are run state; a run written after the damage zone formed and read into a fresh solver
// continues bit for bit as the uninterrupted one.
TEST(CohesiveDCB, RestartDuringPropagationIsBitIdentical) {
  const config::Scene scene = config::load_scene_from_string(dcb_scene(kCohesiveGauss), "dcb.yaml");
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
