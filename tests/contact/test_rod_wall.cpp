// Elastic rod hitting a rigid wall (planar rigid wall, kinematic constraint). Steel column of 100
// cubic elements (h = 1 mm, L = 0.1 m) under uniaxial strain (x, y fixed on every node), moving at
// v0 = 10 m/s towards a fixed wall at z = 0 from a gap g0 = 0.1 mm. One-dimensional elastodynamics:
//   impact at t0 = g0 / v0; a compressive front runs up the rod at c = sqrt(M / rho), M the P-wave
//   modulus; the force on the wall is rho c v0 A while the rod is in contact; the front reflects at
//   the free end and the rod leaves the wall at t0 + 2L/c with velocity -v0.
// Discrete corrections (tolerances): the wall stops the leading node (mass rho A h / 2) in one step,
// which takes its kinetic energy, h / (2L) = 0.5 % of the total: the wall energy is about 0.5 % of
// the initial kinetic energy; the rebound speed converges to v0 as h goes to zero (second test). The contact duration is resolved to a few
// steps out of ~110 plus the front's spread over 2-3 elements (2-3 % of L): 3 %. The plateau (mean
// force over the middle half of the contact) is within 2 % (ringing of the undamped front averages
// out). Energy: KE + IE + wall energy stays at the initial KE to 0.5 %.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "app/application.hpp"
#include "scratch_dir.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kH = 1e-3, kL = 0.1, kV0 = 10.0, kGap = 1e-4;
constexpr double kRho = 7850, kE = 210e9, kNu = 0.3;

std::string rod_scene(int elements) {
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
                           "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
                           "sections:\n  s: {ELFORM: 2, Q1: 0, Q2: 0}\n"
                           "parts:\n  rod: {material: steel, section: s}\n"
                           "mesh:\n  boxes:\n    - {part: rod, origin: [0, 0, 0.0001], size: [" +
                           std::to_string(kL / elements) + ", " + std::to_string(kL / elements) + ", 0.1], elements: [1, 1, " +
                           std::to_string(elements) + "]}\n"
                           "node_sets:\n  all_nodes: all\n"
                           "boundary_conditions:\n  - {node_set: all_nodes, fix: [x, y]}\n"
                           "initial_velocity:\n  - {part: rod, velocity: [0, 0, -10]}\n"
                           "rigid_walls:\n  - {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}\n";
}

// Mean velocity of the rod after it has left the wall.
double rebound(int elements) {
  const model::Model model = test::model_from_yaml(rod_scene(elements), "rod_wall.yaml");
  solver::Solver solver(model);
  const double M = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
  test::run_until(solver, kGap / kV0 + 2 * kL / std::sqrt(M / kRho) + 10e-6);
  double p = 0, m = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i) {
    p += model.mass[i] * solver.state().v[3 * i + 2];
    m += model.mass[i];
  }
  return p / m;
}

TEST(RodOnRigidWall, ImpactTimeDurationPlateauReboundEnergy) {
  const model::Model model = test::model_from_yaml(rod_scene(100), "rod_wall.yaml");
  ASSERT_EQ(model.rigid_walls.size(), 1u);
  solver::Solver solver(model);
  const double M = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
  const double c = std::sqrt(M / kRho);
  const double t0 = kGap / kV0, duration = 2 * kL / c;
  const double plateau = kRho * c * kV0 * kH * kH;
  const double ke0 = 0.5 * kRho * kH * kH * kL * kV0 * kV0;

  double t_first = -1, t_last = -1;
  std::vector<std::pair<double, double>> force;  // (time, wall force)
  double max_energy_error = 0;
  const double t_end = t0 + duration + 10e-6;
  while (solver.state().time < t_end) {
    solver.step();
    const double t = solver.state().time, fn = solver.rigid_walls()[0].normal_force();
    if (fn > 0) {
      if (t_first < 0) t_first = t;
      t_last = t;
    }
    force.push_back({t, fn});
    const auto& e = solver.balance();
    max_energy_error = std::max(max_energy_error, std::abs(e.total() - ke0) / ke0);
  }
  // Rebound: mean velocity of the rod after separation.
  double p = 0, m = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i) {
    p += model.mass[i] * solver.state().v[3 * i + 2];
    m += model.mass[i];
  }
  const double v_rebound = p / m;
  double sum = 0;
  int count = 0;
  for (const auto& [t, fn] : force)
    if (t > t_first + 0.25 * duration && t < t_first + 0.75 * duration) sum += fn, ++count;
  const double f_mean = sum / count;
  std::cout << "rod on wall: impact at " << t_first << " s (theory " << t0 << "), duration " << t_last - t_first
            << " s (2L/c " << duration << "), plateau " << f_mean << " N (rho c v A " << plateau << "), rebound "
            << v_rebound << " m/s, wall energy " << solver.balance().value("rigid_wall") / ke0
            << " of KE0, max energy error " << max_energy_error << "\n";
  EXPECT_NEAR(t_first, t0, 2 * solver.state().dt_prev_half);
  EXPECT_NEAR(t_last - t_first, duration, 0.03 * duration);
  EXPECT_NEAR(f_mean, plateau, 0.02 * plateau);
  EXPECT_LT(v_rebound, kV0);  // its convergence to v0 is the next test
  EXPECT_GT(v_rebound, 0.98 * kV0);
  EXPECT_LT(max_energy_error, 5e-3);
  EXPECT_NEAR(solver.balance().value("rigid_wall") / ke0, kH / (2 * kL), 0.5 * kH / (2 * kL));
}

// The rebound speed falls short of v0 by the energy the discrete rod leaves behind: the leading
// node's kinetic energy taken by the wall (h / 2L, first order in h) and the ringing behind the
// front, which a dispersive lattice spreads over a width growing as h^(2/3) L^(1/3) (order 2/3).
// So halving h divides the shortfall by 2^(2/3) = 1.59 to 2 (asserted 1.5 .. 2.1; measured 1.69
// and 1.71), and the limit of the three speeds (Aitken's extrapolation, which takes the order from
// the data) must be v0: within 0.1 % (measured 0.03 %).
TEST(RodOnRigidWall, ReboundSpeedConvergesToV0) {
  const double v50 = rebound(50), v100 = rebound(100), v200 = rebound(200);
  const double d1 = v100 - v50, d2 = v200 - v100;
  const double limit = v200 + d2 * d2 / (d1 - d2);
  std::cout << "rod rebound: " << v50 << ", " << v100 << ", " << v200 << " m/s at 50, 100, 200 elements; ratios "
            << (kV0 - v50) / (kV0 - v100) << ", " << (kV0 - v100) / (kV0 - v200) << "; limit " << limit << " m/s\n";
  for (double r : {(kV0 - v50) / (kV0 - v100), (kV0 - v100) / (kV0 - v200)}) {
    EXPECT_GT(r, 1.5);
    EXPECT_LT(r, 2.1);
  }
  EXPECT_NEAR(limit, kV0, 1e-3 * kV0);
}

// The wall's force as history.csv shows it starts when the rod's face reaches the wall. Before
// the wall acts the rod translates freely, so the face's gap at a row's time t is g0 - v0 t
// exactly. The wall is a one-step constraint: the force at t^n is the one that lands the face on
// the wall at t^{n+1}, so the first row with a force has the face within one step's travel of
// the wall, 0 <= gap < v0 dt^{n+1/2}, and every earlier row has zero force. (The rows used to
// print the wall force of the next cycle: the force began at a gap of 1.7 steps' travel.) The
// column's impulse, sum F dt_n with dt_n = (dt^{n-1/2} + dt^{n+1/2}) / 2, is the rod's momentum
// change M (v0 + v_rebound); with v_rebound = 0.991 v0 (the 1-D answer v0 less the discrete
// shortfall of the test above, < 1 %) it is 2 M v0 within 1 %.
TEST(RodOnRigidWall, HistoryForceStartsWhenTheFaceReachesTheWall) {
  namespace fs = std::filesystem;
  test::ScratchDir dir;
  const fs::path scene = dir.path() / "rod_wall.yaml";
  const double M = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
  const double t_end = kGap / kV0 + 2 * kL / std::sqrt(M / kRho) + 5e-6;
  std::ofstream(scene) << rod_scene(100) << "output: {history_interval: 1.0e-12}\n";
  std::ostringstream o, e;
  const int code = app::run_application({"run", scene.string(), "-o", (dir.path() / "out").string(), "--set",
                                         "control.termination_time=" + std::to_string(t_end)},
                                        o, e);
  ASSERT_EQ(code, 0) << e.str() << o.str();
  std::ifstream in(dir.path() / "out" / "history.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) names.push_back(c);
  std::map<std::string, std::vector<double>> h;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::size_t k = 0;
    for (std::string v; std::getline(row, v, ','); ++k) h[names.at(k)].push_back(std::strtod(v.c_str(), nullptr));
  }
  const auto& t = h.at("time");
  const auto& dt = h.at("dt");
  const auto& fn = h.at("wall_floor_normal");
  std::size_t first = 0;
  while (first < fn.size() && fn[first] == 0) ++first;
  ASSERT_LT(first + 1, fn.size()) << "the rod never touched the wall";
  ASSERT_GT(first, 0u);
  const double gap = kGap - kV0 * t[first], travel = kV0 * dt[first + 1];
  double impulse = 0;
  for (std::size_t i = first; i < fn.size(); ++i) impulse += fn[i] * 0.5 * (dt[i] + dt[i + 1 < dt.size() ? i + 1 : i]);
  const double mass = kRho * kH * kH * kL;
  std::cout << "rod on wall (history): first force at t = " << t[first] << " s with the face " << gap
            << " m from the wall (one step's travel " << travel << " m); impulse / (2 M v0) "
            << impulse / (2 * mass * kV0) << "\n";
  EXPECT_GE(gap, 0.0);
  EXPECT_LT(gap, travel);
  EXPECT_EQ(fn.back(), 0.0) << "the rod had not left the wall at the end";
  EXPECT_NEAR(impulse, 2 * mass * kV0, 0.01 * 2 * mass * kV0);
}

}  // namespace
}  // namespace plyimpact
