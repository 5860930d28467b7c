// The double cantilever beam of test_dcb.cpp, test_cohesive_dcb.cpp and test_cohesive_dcb_mesh.cpp:
// scene, corrected beam theory, a solver run recording the load at the loading block, and the load
// smoothed over a window. Two unidirectional arms (h = 1.5 mm, 2 elements each, ELFORM 1 with IHQ 6),
// width b = 2 mm, length 60 mm, one delaminating interface given by the caller, the arm ends (x = 0)
// pulled apart in z at velocities that ramp up as (1 - cos) over 0.6 ms, then stay at 0.7 m/s.
//
// Corrected beam theory (J. G. Williams, "End corrections for orthotropic DCB specimens", Compos.
// Sci. Technol. 35 (1989) 367-376; ASTM D5528):
//   C = delta / P = 8 (a + Delta)^3 / (E11 b h^3), Delta = chi h,
//   chi = sqrt(E11 / (11 G13) (3 - 2 (Gamma / (1 + Gamma))^2)), Gamma = 1.18 sqrt(E11 E22) / G13;
//   propagation at P_c = b / (a + Delta) sqrt(E11 h^3 G_Ic / 12);
//   propagation branch P(delta) = sqrt(8 b^2 (E11 h^3 G_Ic / 12)^(3/2) / (E11 h^3 delta)).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "interface/interface_tiebreaks.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

namespace plyimpact::dcb {

constexpr double E11 = 120e9, E22 = 10e9, G13 = 5e9;  // Pa
constexpr double h = 1.5e-3, b = 2e-3, a0 = 25e-3;     // m: arm thickness, width, pre-crack
constexpr double GIc = 200;                            // J/m^2
constexpr double kRamp = 0.6e-3;                       // s, the (1 - cos) velocity ramp
// m/s, each arm (test_dcb.cpp): the opening reaches 2.5 delta_c by 2.5 ms with the arms' kinetic
// energy below 1 % of their strain energy at delta_c.
constexpr double kOpeningRate = 0.7;
// s: the load is the reaction's mean over this window centred on each sample, which spans several
// periods of the tip nodes' and the through-thickness modes and a fraction of the arms' bending
// period (0.3 ms at a0).
constexpr double kWindow = 0.1e-3;

// The scene: `interfaces` is the laminate's interfaces value, `end` the termination time (s),
// `segment` the in-plane element size (mm).
inline std::string dcb_scene(const std::string& interfaces, double end, double segment = 1) {
  std::ostringstream y;
  y << "units: mm-t-s-MPa\n"
       "control: {termination_time: " << end << "}\n"
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
       "  material: ud\n  section: arm\n  elements_per_ply: 2\n  element_size: " << segment << "\n"
       "  interfaces: " << interfaces << "\n"
       "node_sets:\n"
       "  tip_top: {box: {min: [-0.01, -1, 1.6], max: [0.01, 3, 3.1]}}\n"
       "  tip_bottom: {box: {min: [-0.01, -1, -0.1], max: [0.01, 3, 1.4]}}\n"
       "boundary_conditions:\n";
  // v(t) = V (1 - cos(pi t / t_r)) / 2 up to t_r, then V, sampled finely enough that the
  // piecewise-linear curve is smooth to 0.3 % of V.
  for (int side = 0; side < 2; ++side) {
    y << "  - {node_set: " << (side == 0 ? "tip_top" : "tip_bottom") << ", velocity: {dofs: [z], curve: [";
    const double sign = side == 0 ? 1 : -1;
    for (int i = 0; i <= 24; ++i) {
      const double t = kRamp * i / 24;
      y << "[" << t << " s, " << sign * kOpeningRate * 0.5 * (1 - std::cos(std::numbers::pi * t / kRamp)) << " m/s], ";
    }
    y << "[" << end << " s, " << sign * kOpeningRate << " m/s]]}}\n";
  }
  return y.str();
}

inline double williams_delta() {
  const double gamma = 1.18 * std::sqrt(E11 * E22) / G13;
  const double r = gamma / (1 + gamma);
  return h * std::sqrt(E11 / (11 * G13) * (3 - 2 * r * r));
}
inline double compliance(double a) { return 8 * std::pow(a + williams_delta(), 3) / (E11 * b * h * h * h); }
inline double critical_load(double a) { return b / (a + williams_delta()) * std::sqrt(E11 * h * h * h * GIc / 12); }
inline double critical_opening(double a) { return compliance(a) * critical_load(a); }
inline double propagation_load(double delta) {
  return std::sqrt(8 * b * b * std::pow(E11 * h * h * h * GIc / 12, 1.5) / (E11 * h * h * h * delta));
}

inline const interface::InterfaceTiebreaks* interfaces_of(const solver::Solver& s) {
  for (const auto& c : s.contributors())
    if (auto* p = dynamic_cast<const interface::InterfaceTiebreaks*>(c.get())) return p;
  return nullptr;
}

// A run's record: per cycle the time, the opening (twice the tip's z displacement) and the load
// (|z reaction| of the loading block), and the energy checks.
struct Record {
  std::vector<double> times, openings, loads;
  double max_ratio_err = 0;  // |energy ratio - 1| once the external work exceeds the threshold
  double min_elastic = 0, min_dissipated = 0;
  long cycles = 0;
  double wall = 0, cpu = 0;  // s: wall clock and process CPU time of the run
};

// Steps `solver` to `end`; the energy ratio is judged once the external work exceeds `work_threshold`.
inline Record record_run(solver::Solver& solver, const model::Model& model, double end, double work_threshold) {
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  const auto& tops = model.node_sets[model.constrained_sets[0]];  // tip_top: first in constraint order
  Record r;
  double opening = 0;
  while (solver.state().time < end * (1 - 1e-12)) {
    const double dt = solver.state().dt_next_half;
    solver.step();
    const auto& s = solver.state();
    opening += 2 * s.v[3 * std::size_t(tops.nodes[0]) + 2] * dt;
    r.times.push_back(s.time);
    r.openings.push_back(opening);
    r.loads.push_back(std::abs(s.reaction[2]));
    if (solver.balance().external_work() > work_threshold)
      r.max_ratio_err = std::max(r.max_ratio_err, std::abs(solver.energy_ratio() - 1));
    r.min_elastic = std::min(r.min_elastic, solver.balance().value("interface_elastic"));
    r.min_dissipated = std::min(r.min_dissipated, solver.balance().value("interface_dissipated"));
  }
  r.cycles = solver.state().cycle;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  r.cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return r;
}

// The load-opening curve: the load's mean over kWindow centred on each sample (samples whose window
// leaves the run are dropped); the openings increase monotonically.
struct Curve {
  std::vector<double> times, opening, load;
};
inline Curve smoothed(const Record& r) {
  Curve c;
  std::size_t lo = 0, hi = 0;
  double sum = 0;
  for (std::size_t i = 0; i < r.times.size(); ++i) {
    if (r.times[i] - kWindow / 2 < 0 || r.times[i] + kWindow / 2 > r.times.back()) continue;
    while (hi < r.times.size() && r.times[hi] <= r.times[i] + kWindow / 2) sum += r.loads[hi++];
    while (r.times[lo] < r.times[i] - kWindow / 2) sum -= r.loads[lo++];
    c.times.push_back(r.times[i]);
    c.opening.push_back(r.openings[i]);
    c.load.push_back(sum / double(hi - lo));
  }
  return c;
}

// Load of `c` at `opening` (linear interpolation).
inline double load_at(const Curve& c, double opening) {
  const auto it = std::lower_bound(c.opening.begin(), c.opening.end(), opening);
  if (it == c.opening.begin()) return c.load.front();
  if (it == c.opening.end()) return c.load.back();
  const std::size_t k = std::size_t(it - c.opening.begin());
  const double w = (opening - c.opening[k - 1]) / (c.opening[k] - c.opening[k - 1]);
  return c.load[k - 1] + w * (c.load[k] - c.load[k - 1]);
}

inline double peak_of(const Curve& c, double* at = nullptr) {
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
inline Difference difference(const Curve& ref, const Curve& other, double until) {
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

}  // namespace plyimpact::dcb
