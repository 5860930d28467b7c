// Mixed-mode bending: the shipped scene configs/mmb_t800s_m21.yaml (the ENF beam with the upper arm's
// end lifted over the left support while the mid-span is pushed down, the lever replaced by a fixed
// ratio of the two prescribed velocities; see the scene's header) at CI size (b = 2 mm), three ratios
// giving three mixities, each at three meshes (segments 5, 2.5, 1.25 mm).
//
// Independent answer: the mixed-mode criterion of the scene's law at initiation, with the energy
// release rates from beam theory and Reeder & Crews' superposition (AIAA J. 28 (1990) 1270-1276):
// R_e the end's lifting load, R_m the mid-span load, P_I = R_e - R_m / 4, P_II = R_m,
//   G_I  = 12 P_I^2 (a + Delta_I)^2 / (b^2 h^3 E11)        (DCB, Williams' Delta_I = chi h),
//   G_II = 9 P_II^2 (a + Delta_II)^2 / (16 b^2 h^3 E11)    (ENF, Delta_II = 0.42 Delta_I),
// PARAM = 1: the linear power law G_I / G_Ic + G_II / G_IIc = 1. Initiation: the loads averaged over
// the 0.05 ms before the first history row at which the crack front has moved.
// Tolerance: the criterion's value f = G_I/G_Ic + G_II/G_IIc within 0.25 of 1 at the finest mesh
// (1.25 mm). G goes with the load squared, and the load carries two known errors of these meshes
// with the seed's full strengths: the mode II process zone (~9 mm, a third of a0) puts the ENF peak
// ~8.5 % below LEFM (test_enf), i.e. ~17 % low in G_II; the mode I zone (T07: 1.6 mm at NFLS 60 MPa)
// spans only 1.3 segments at 1.25 mm, which overshoots the mode I load (test_cohesive_zone_length:
// +43 % at 1.6 segments). The two pull f in opposite directions, so f rises as the mixity moves
// towards mode I; the coarser meshes, with fewer segments in both zones, are printed to show it.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "config/overrides.hpp"
#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "run/run.hpp"

namespace plyimpact {
namespace {

constexpr double E11 = 157e9, E22 = 8.5e9, G13 = 4.2e9;  // Pa
constexpr double h = 1.5e-3, b = 2e-3;
constexpr double GIc = 765, GIIc = 1250;  // J/m^2

double delta_i() {
  const double gamma = 1.18 * std::sqrt(E11 * E22) / G13;
  const double r = gamma / (1 + gamma);
  return h * std::sqrt(E11 / (11 * G13) * (3 - 2 * r * r));
}

// Columns of a CSV by name.
std::vector<std::vector<double>> read_columns(const std::filesystem::path& file, const std::vector<std::string>& names) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) header.push_back(c);
  std::vector<std::size_t> idx;
  for (const auto& n : names) idx.push_back(std::size_t(std::find(header.begin(), header.end(), n) - header.begin()));
  std::vector<std::vector<double>> out(names.size());
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) row.push_back(std::stod(c));
    for (std::size_t k = 0; k < idx.size(); ++k) out[k].push_back(idx[k] < row.size() ? row[idx[k]] : NAN);
  }
  return out;
}

struct MmbResult {
  double f = 0, mixity = 0, wall = 0;
  long elements = 0;
};

MmbResult run_mmb(double segment_mm, double end_velocity) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<config::SceneOverride> o;
  for (const std::string s :
       {"laminate.width=2", "node_sets.support_left.box.max=[5.01, 3, 0.01]",
        "node_sets.support_right.box.max=[105.01, 3, 0.01]", "node_sets.load_line.box.max=[55.01, 3, 3.01]",
        "node_sets.end_hinge.box.max=[5.01, 3, 3.01]", "control.termination_time=3.8e-3", "output.interval=10e-3",
        "output.history_interval=5e-6"})
    o.push_back(config::parse_set_argument(s));
  o.push_back(config::parse_set_argument("laminate.element_size=" + std::to_string(segment_mm)));
  o.push_back(config::parse_set_argument("boundary_conditions[3].velocity.value=" + std::to_string(end_velocity) +
                                         " m/s"));
  const config::Scene scene =
      config::load_scene(std::string(PLYIMPACT_SOURCE_DIR) + "/configs/mmb_t800s_m21.yaml", o);
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  run::RunOptions options;
  options.output_dir = std::filesystem::path(PLYIMPACT_BINARY_DIR) / "test_output" /
                       ("mmb_" + std::to_string(int(segment_mm * 1000)) + "_" + std::to_string(int(end_velocity * 100)));
  const run::RunReport report = run::run_model(model, options);
  EXPECT_TRUE(report.completed) << report.stop_reason;
  const auto cols =
      read_columns(report.history, {"time", "reaction_end_hinge_fz", "reaction_load_line_fz", "crack_length"});
  const auto& t = cols[0];
  const auto& a = cols[3];
  std::size_t grow = 1;
  while (grow < a.size() && a[grow] <= a[0]) ++grow;
  EXPECT_LT(grow, a.size()) << "the crack grew";
  double re = 0, rm = 0;
  int n = 0;
  for (std::size_t i = 0; i < grow; ++i)
    if (t[i] >= t[grow] - 0.05e-3) {
      re += cols[1][i];
      rm += -cols[2][i];
      ++n;
    }
  re /= n;
  rm /= n;
  const double a0 = a[0];
  const double p_i = re - rm / 4, p_ii = rm;
  const double g_i = 12 * p_i * p_i * std::pow(a0 + delta_i(), 2) / (b * b * h * h * h * E11);
  const double g_ii = 9 * p_ii * p_ii * std::pow(a0 + 0.42 * delta_i(), 2) / (16 * b * b * h * h * h * E11);
  MmbResult r;
  r.f = g_i / GIc + g_ii / GIIc;
  r.mixity = g_ii / (g_i + g_ii);
  r.elements = long(model.num_elements());
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

TEST(MMB, InitiationOnTheMixedModeCriterionAtThreeMixities) {
  std::printf("MMB (T800S/M21, L 50 mm, a0 30 mm, b 2 mm), mid-span 1 m/s down; linear power law\n");
  std::printf("  end velocity  segment  elements  G_II/G   f = GI/GIc + GII/GIIc  wall\n");
  for (double ve : {0.6, 1.2, 2.4}) {
    for (double seg : {5.0, 2.5, 1.25}) {
      const MmbResult r = run_mmb(seg, ve);
      std::printf("  %8.2f m/s  %5.3f mm  %8ld  %6.3f  %10.3f (%+.1f %%)  %5.1f s\n", ve, seg, r.elements, r.mixity, r.f,
                  100 * (r.f - 1), r.wall);
      if (seg < 2) {
        EXPECT_NEAR(r.f, 1.0, 0.25) << "end velocity " << ve << " m/s";
      }
    }
  }
}

}  // namespace
}  // namespace plyimpact
