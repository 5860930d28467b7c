// Richardson extrapolation on a project case with an exact answer, run as a convergence study:
// the longitudinal wave in a laterally constrained steel bar (uniaxial strain, bar_wave.yaml's
// material), pushed at 10 m/s at x = 0 and fixed at x = L = 100 mm, on 50, 100 and 200 elements
// along the bar (h = 2, 1, 0.5 mm). Arrival time: the first time the reaction at the fixed end
// reaches rho c v A, half of its reflected plateau 2 rho c v A; exact L / c with
// c = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu)) / rho). Bulk viscosity off (Q1 = Q2 = 0) so that the
// front is shaped by the mesh's dispersion alone: a lumped-mass linear chain turns a step into an
// Airy front of width ~ (h^2 c t)^(1/3), so the half-level crossing moves by O(h^(2/3)); sampling
// the crossing by linear interpolation between cycles adds an O(dt) = O(h) part. Asserted: the
// differences are monotone, the observed order lies in [0.5, 1] (between those two rates), and the
// extrapolated arrival is at least 4 times closer to L / c than the finest mesh (measured: 35
// times, 7.8e-5 against 2.7e-3 relative).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "output/history_table.hpp"
#include "output/json_reader.hpp"
#include "study/richardson.hpp"
#include "study/study.hpp"
#include "study/study_spec.hpp"
#include "study_support.hpp"

namespace plyimpact::study {
namespace {

const char* kBar =
    "units: mm-t-s-MPa\ncontrol: {termination_time: 2.4e-5}\noutput: {interval: 2.4e-5, history_interval: 1.0e-9}\n"
    "materials:\n  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}\n"
    "sections:\n  hex1: {ELFORM: 1, IHQ: 4, QM: 0.1, Q1: 0, Q2: 0}\nparts:\n  bar: {material: steel, section: hex1}\n"
    "mesh:\n  boxes:\n    - {part: bar, size: [100, 2, 2], elements: [50, 1, 1]}\n"
    "node_sets:\n  left: {plane: {axis: x, value: 0}}\n  right: {plane: {axis: x, value: 100}}\n  all_nodes: all\n"
    "boundary_conditions:\n  - {node_set: all_nodes, fix: [y, z]}\n  - {node_set: right, fix: [x]}\n"
    "  - {node_set: left, velocity: {dofs: [x], value: 10 m/s}}\n";

const char* kStudy =
    "scene: bar.yaml\n"
    "parameters:\n"
    "  mesh.boxes[0].elements: [[50, 1, 1], [100, 1, 1], [200, 1, 1]]\n"
    "quantities: [wall_time, cycles]\n"
    "threads: 1\n"
    "convergence: {parameter: 'mesh.boxes[0].elements', h: [2.0e-3, 1.0e-3, 0.5e-3]}\n";

constexpr double kE = 210e9, kNu = 0.3, kRho = 7850, kV = 10, kArea = 4e-6, kLength = 0.1;

// First crossing of rho c v A by |reaction_right_fx|, interpolated linearly between samples.
double arrival_time(const std::filesystem::path& history, double c) {
  const auto t = output::read_history_csv(history);
  const int ti = t.column_index("time"), fi = t.column_index("reaction_right_fx");
  EXPECT_GE(fi, 0);
  const double level = kRho * c * kV * kArea;
  for (std::size_t i = 1; i < t.rows(); ++i) {
    const double f0 = std::abs(t.at(i - 1, fi)), f1 = std::abs(t.at(i, fi));
    if (f1 >= level) return t.at(i - 1, ti) + (t.at(i, ti) - t.at(i - 1, ti)) * (level - f0) / (f1 - f0);
  }
  ADD_FAILURE() << "the wave never arrived in " << history;
  return std::nan("");
}

TEST(BarConvergence, RichardsonOnTheWaveArrival) {
  test::ScratchDir d;
  test::write_file(d.path() / "bar.yaml", kBar);
  const auto file = test::write_file(d.path() / "bar_study.yaml", kStudy);
  StudyOptions o;
  o.program = test::kProgram;
  o.output_dir = d.path() / "out";
  std::ostringstream log;
  const auto r = run_study(read_study(file), o, log);
  ASSERT_EQ(r.failed, 0u) << log.str();
  const output::Json conv = output::read_json_file(d.path() / "out" / "study.json");
  const auto& meshes = conv.find("convergence")->find("meshes")->as_array();
  ASSERT_EQ(meshes.size(), 3u);
  const double c = std::sqrt(kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)) / kRho), exact = kLength / c;
  double h[3], q[3];
  for (std::size_t i = 0; i < 3; ++i) {
    h[i] = meshes[i].find("h")->as_number();
    q[i] = arrival_time(d.path() / "out" / meshes[i].find("case")->as_string() / "history.csv", c);
  }
  EXPECT_DOUBLE_EQ(h[0], 2e-3);  // coarse first
  const RichardsonResult rr = richardson(h, q, 0.5, 1.0);
  ASSERT_TRUE(rr.extrapolated) << (rr.flags.empty() ? "" : rr.flags.front());
  EXPECT_TRUE(rr.asymptotic) << "observed order " << rr.order;
  const double err_finest = std::abs(q[2] - exact) / exact, err_extrapolated = std::abs(rr.value - exact) / exact;
  EXPECT_LT(err_extrapolated, err_finest / 4) << "finest " << err_finest << ", extrapolated " << err_extrapolated;
  std::cout << "wave arrival: observed order " << rr.order << ", relative error finest " << err_finest
            << ", extrapolated " << err_extrapolated << "\n";
}

}  // namespace
}  // namespace plyimpact::study
