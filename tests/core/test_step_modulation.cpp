// Energy conservation of a free elastic vibration whose own stable step controls the run, at
// TSSFAC 0.85, 0.88 and 0.9 with the default bulk viscosity Q2 = 0.06 (Q1 = 0: the Q2 term is the
// one that switches on and off with every compression at any amplitude).
//
// Cause of the failure this guards against: the element step L / (Q + sqrt(Q^2 + c^2)) has
// Q = Q2 c (+ Q1 term) only while the element compresses, so a step taken afresh every cycle rises
// and falls at twice the frequency of the vibration, and a central-difference scheme whose step is
// modulated in phase with a mode is parametrically pumped. The solver now holds the Q of the step
// and lets it decay by only 0.1 % per cycle (solver/element_step.hpp, step_q); this checks the result.
//
// Case: one hex of side t with every node fixed in x and y (as test_bulk_viscosity_step.cpp), so
// its only motion is the thickness mode, omega = 2 c / t with the wave modulus, exactly the step's
// L/c bound (no free-corner mode above it, docs/theory.md section 2), started closing at v0 (its faces
// at -+v0/2). Independent answer: the discrete energy of the leapfrog scheme,
//   E* = 1/2 sum m v^{n-1/2} . v^{n+1/2} + IE + BV,
// with BV the booked bulk-viscous work (trapezoid rule), is conserved by a constant step
// (test_energy_conservation.cpp derives it). Its value is fixed by the start: the solver starts
// from v^{-1/2} = v^0 - dt/2 f^0/m, and f^0 is the viscous force of the closing velocity,
// -2 xi omega v0 per unit reduced mass with xi = Q2 (test_bulk_viscosity_step.cpp), so
//   E* = E0 (1 - (xi omega dt0)^2),  dt0 = TSSFAC (sqrt(1 + xi^2) - xi) t / c,
// 0.9897 at TSSFAC 0.9. Measured with the step held fixed at dt0: within 3e-4 of that over 3000
// cycles (about 850 periods); asserted to 1e-3 (the reference is right). With the solver's own step:
// within 0.16 % (0.9: -0.16 %, 0.88: +0.11 %): the held Q still decays by up to 0.35 % between
// compressions and jumps back at each, a step change of ~0.02 %. Tolerance 0.5 % at every cycle
// after the first. Without the held Q, E*/E0 reached 3e7 (TSSFAC 0.85) and 1.3e10 (0.88) within
// 1200 cycles and at 0.9 fell to 0.547 (45 % lost unbooked); a global limit of 0.1 %/cycle on the
// rise of the step instead of the held Q left +2.2 % (0.88) and -2.4 % (0.9).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <cmath>
#include <string>
#include <vector>

#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kT = 1e-3;   // element side, m
constexpr double kV0 = 0.1;   // closing speed, m/s (strain ~ 1e-5: linear)
constexpr int kCycles = 3000;
constexpr double kE = 210e9, kNu = 0.3, kRho = 7850;  // steel, as in the scene

struct Range {
  double lo = 1e300, hi = -1e300;
};

Range run(double tssfac, int elform, bool fixed = false) {
  const std::string t = std::to_string(kT);
  const std::string section = elform == 2 ? "{ELFORM: 2, Q1: 0, Q2: 0.06}" : "{ELFORM: 1, IHQ: 3, Q1: 0, Q2: 0.06}";
  model::Model m = test::model_from_yaml(
      "units: SI\ncontrol: {termination_time: 1.0, energy_ratio_limit: 0, tssfac: " + std::to_string(tssfac) + "}\n"
      "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: " + section + "\n"
      "parts:\n  cube: {material: steel, section: s}\n"
      "mesh:\n  boxes:\n    - {part: cube, size: [" + t + ", " + t + ", " + t + "], elements: [1, 1, 1]}\n"
      "node_sets:\n  all_nodes: all\nboundary_conditions:\n  - {node_set: all_nodes, fix: [x, y]}\n",
      "cube.yaml");
  for (std::size_t n = 0; n < m.num_nodes(); ++n) m.v0[3 * n + 2] = m.X[3 * n + 2] > 0.5 * kT ? -0.5 * kV0 : 0.5 * kV0;
  solver::Solver s(m);
  const double e0 = s.balance().kinetic(), dt_first = s.state().dt_next_half;  // dt0 (closing: Q on)
  Range r;
  std::vector<double> v_old;
  for (int c = 0; c < kCycles; ++c) {
    v_old = s.state().v;  // v^{n-1/2}
    if (fixed) s.state().dt_next_half = dt_first;
    s.step();
    const auto& b = s.balance();
    double k_shadow = 0;
    for (std::size_t i = 0; i < v_old.size(); ++i) k_shadow += 0.5 * m.mass[i / 3] * v_old[i] * s.state().v[i];
    const double e = (k_shadow + b.internal() + b.hourglass() + b.bulk_viscous()) / e0;
    if (c > 0) r.lo = std::min(r.lo, e), r.hi = std::max(r.hi, e);  // cycle 0: v_old is v^0, not v^{-1/2}
  }
  return r;
}

TEST(StepModulation, ThicknessModeConservesEnergyAtTssfacUpTo09) {
  const double M = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)), c = std::sqrt(M / kRho), omega = 2 * c / kT;
  const double xi = 0.06;
  for (int elform : {2, 1})
    for (double tssfac : {0.85, 0.88, 0.9}) {
      const double dt0 = tssfac * (std::sqrt(1 + xi * xi) - xi) * kT / c;
      const double expected = 1 - std::pow(xi * omega * dt0, 2);
      for (bool fixed : {true, false}) {
        const std::string what = "ELFORM " + std::to_string(elform) + ", TSSFAC " + std::to_string(tssfac) +
                                 (fixed ? ", step fixed at dt0" : ", solver's step");
        Range r;
        try {
          r = run(tssfac, elform, fixed);
        } catch (const RunError& e) {
          ADD_FAILURE() << what << ": " << e.what();
          continue;
        }
        const double tol = fixed ? 1e-3 : 5e-3;
        EXPECT_LE(r.hi / expected, 1 + tol) << what << ": energy gained";
        EXPECT_GE(r.lo / expected, 1 - tol) << what << ": energy lost unbooked";
        std::cout << what << ": E*/E0 in [" << r.lo << ", " << r.hi << "], expected " << expected << "\n";
      }
    }
}

}  // namespace
}  // namespace plyimpact
