// End-notched flexure (mode II): the shipped scene configs/enf_t800s_m21.yaml at CI size (a 2 mm
// wide strip; span, thickness and a0 as shipped: L = 50 mm, h = 1.5 mm per arm, a0 = 30 mm from the
// left support) through the whole chain at three meshes (segments 5, 2.5, 1.25 mm: the node
// lines of the supports and the load exist on all three), with the seed's full strengths.
//
// Independent answers, beam theory for three-point bending of the two arms (each of thickness h,
// width b, span 2L, crack a from the support):
//   compliance C = (3 (a + Delta_II)^3 + 2 L^3) / (8 E11 b h^3) + L / (2 kappa G13 b (2 h))
//     (Russell & Street 1985 for the bending term, with the crack-tip rotation correction
//     Delta_II = 0.42 Delta_I of Wang & Williams, Compos. Sci. Technol. 43 (1992) 251-256, Delta_I the
//     DCB correction of Williams 1989; the second term is the Timoshenko shear deflection of the span,
//     kappa = 5/6, 3 % of the total here);
//   G_II = 9 P^2 (a + Delta_II)^2 / (16 b^2 E11 h^3), so the crack starts at
//   P_c = 4 b / (3 (a + Delta_II)) sqrt(E11 h^3 G_IIc); with a0 / L = 0.6 < 0.7 the growth is
//   unstable, so P_c is the peak load.
// Tolerances:
//   - compliance (fit of deflection against load over 0.3 .. 0.8 P_c, the load averaged over 0.1 ms)
//     within 2 % plus the tip term at each mesh: beam theory with these corrections agrees with 2-D
//     elasticity to ~2 % (Wang & Williams; it leaves out the local compliance at the load and
//     support lines, a fraction of a per cent here), and the mesh places the crack tip only to
//     within its segment: the first bonded pair's tributary half-segment is counted as open
//     (a + seg / 2), uncertain by a quarter segment either way, so the tip term is the beam
//     compliance's change over a quarter segment, C(a + seg / 4) / C(a) - 1: 3.6, 1.7, 0.8 % at
//     5, 2.5, 1.25 mm. Measured +5.4, +2.5, +1.7 %, converging on the beam answer; at 5 mm about
//     1 % of it depends on the bulk viscosity (Q1 = 0: +5.2 %; Q1 = Q2 = 0: +4.7 %, but that run
//     does not complete) - a dynamic test's load carries the one-sided viscous pressure;
//   - peak load within 15 % of P_c at the finest mesh: in mode II the process zone of a slender
//     beam is long, of order sqrt(E11 h G_IIc) / SFLS = 9 mm (Massabo & Cox's scaling for slender
//     bodies), a third of a0, so the cohesive peak lies below the LEFM value (the zone relieves the
//     tip) by roughly the ratio of half the zone to a + Delta_II (14 %); the coarser meshes are printed
//     (the segments 5 mm to 1.25 mm put 2 to 7 segments in that zone).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "config/overrides.hpp"
#include "config/scene_loader.hpp"
#include "fracture/dcb_record.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "run/run.hpp"

namespace plyimpact {
namespace {

constexpr double E11 = 157e9, E22 = 8.5e9, G13 = 4.2e9;  // Pa, the scene's card
constexpr double h = 1.5e-3, b = 2e-3, L = 50e-3, a0 = 30e-3;
constexpr double GIIc = 1250;  // J/m^2, ERATES

double delta_ii() {
  const double gamma = 1.18 * std::sqrt(E11 * E22) / G13;
  const double r = gamma / (1 + gamma);
  return 0.42 * h * std::sqrt(E11 / (11 * G13) * (3 - 2 * r * r));
}

// Beam-theory compliance (m/N) for a crack of length a from the support (see the header).
double beam_compliance(double a) {
  return (3 * std::pow(a + delta_ii(), 3) + 2 * L * L * L) / (8 * E11 * b * h * h * h) +
         L / (2 * 5.0 / 6.0 * G13 * b * 2 * h);
}

struct EnfResult {
  double compliance = 0, peak = 0, wall = 0;
  long elements = 0;
};

EnfResult run_enf(double segment_mm) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<config::SceneOverride> o;
  for (const std::string s :
       {"laminate.width=2", "node_sets.support_left.box.max=[5.01, 3, 0.01]",
        "node_sets.support_right.box.max=[105.01, 3, 0.01]", "node_sets.load_line.box.max=[55.01, 3, 3.01]",
        "control.termination_time=3.8e-3", "output.interval=10e-3", "output.history_interval=5e-6",
        "boundary_conditions[2].velocity.ramp=0.75 ms"})
    o.push_back(config::parse_set_argument(s));
  o.push_back(config::parse_set_argument("laminate.element_size=" + std::to_string(segment_mm)));
  const config::Scene scene =
      config::load_scene(std::string(PLYIMPACT_SOURCE_DIR) + "/configs/enf_t800s_m21.yaml", o);
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  run::RunOptions options;
  options.output_dir = std::filesystem::path(PLYIMPACT_BINARY_DIR) / "test_output" /
                       ("enf_" + std::to_string(int(segment_mm * 1000)));
  const run::RunReport report = run::run_model(model, options);
  EXPECT_TRUE(report.completed) << report.stop_reason;
  const fracture::DcbRecord rec = fracture::read_dcb_record(report.history.string(), {}, {});
  const double a = rec.rows.front().point.a;
  const double p_c = 4 * b / (3 * (a + delta_ii())) * std::sqrt(E11 * h * h * h * GIIc);
  EnfResult r;
  r.elements = long(model.num_elements());
  double sxx = 0, sxy = 0;
  constexpr std::size_t kHalf = 10;  // 0.1 ms mean of the load (5 us rows)
  for (std::size_t i = kHalf; i + kHalf < rec.rows.size(); ++i) {
    double p = 0;
    for (std::size_t j = i - kHalf; j <= i + kHalf; ++j) p += rec.rows[j].point.P;
    p /= double(2 * kHalf + 1);
    r.peak = std::max(r.peak, p);
    if (rec.rows[i].point.a == a && p > 0.3 * p_c && p < 0.8 * p_c && r.peak < 0.8 * p_c) {
      sxx += p * p;
      sxy += p * rec.rows[i].point.delta;
    }
  }
  r.compliance = sxy / sxx;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

TEST(ENF, ComplianceAndCriticalLoadAgainstBeamTheoryAtThreeMeshes) {
  std::printf("ENF (T800S/M21, L %.0f mm, a0 %.0f mm, b %.0f mm, 2h %.0f mm), Delta_II %.2f mm\n", L * 1e3, a0 * 1e3,
              b * 1e3, 2 * h * 1e3, delta_ii() * 1e3);
  std::printf("  segment  elements  compliance error  peak / P_c - 1  wall\n");
  for (double seg : {5.0, 2.5, 1.25}) {
    const EnfResult r = run_enf(seg);
    const double a_eff = a0 + seg * 1e-3 / 2;
    const double c_beam = beam_compliance(a_eff);
    const double tolerance = 0.02 + beam_compliance(a_eff + seg * 1e-3 / 4) / c_beam - 1;
    const double p_c = 4 * b / (3 * (a_eff + delta_ii())) * std::sqrt(E11 * h * h * h * GIIc);
    std::printf("  %5.3f mm  %8ld  %+14.2f %%  %+13.2f %%  %5.1f s\n", seg, r.elements,
                100 * (r.compliance / c_beam - 1), 100 * (r.peak / p_c - 1), r.wall);
    EXPECT_NEAR(r.compliance / c_beam, 1.0, tolerance) << "segment " << seg << " mm";
    if (seg < 2) {
      EXPECT_NEAR(r.peak / p_c, 1.0, 0.15);
    }
  }
}

}  // namespace
}  // namespace plyimpact
