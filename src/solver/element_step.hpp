// Stable step, bulk viscosity and the per-chunk checks shared by the element families.
#pragma once

#include <cmath>

#include "solver/element_update.hpp"

namespace plyimpact::solver {

// Stable element step (LS-DYNA Theory Manual, time step control for solids) with the bulk
// viscosity term: L / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 L |tr D| in compression, L = V / A_max.
// This is the exact central-difference limit (L/c)(sqrt(1 + xi^2) - xi) of the element's highest
// mode, omega = 2c/L, under the explicit (v^{n+1/2}) viscous damping xi = Q/c that the bulk
// viscosity below gives that mode, provided the viscosity uses the same length L (see there).
inline double element_time_step(double L, double c, double Q) { return L / (Q + std::sqrt(Q * Q + c * c)); }

// Relative decay per cycle of the Q held for the step (step_q).
constexpr double kStepQDecay = 1e-3;

// Q of the step: the bulk-viscosity term of this cycle (0 in expansion), or the element's last held
// Q decayed by kStepQDecay, whichever is larger. Why held: with Q taken afresh the step drops 5.8 %
// (Q2 = 0.06: sqrt(1 + Q2^2) - Q2 = 0.942) whenever the controlling element compresses and comes
// back when it expands, i.e. it oscillates at twice the frequency of the vibration, and a
// central-difference scheme whose step is modulated in phase with a mode is parametrically pumped:
// a one-element thickness mode that controls its own step grew by 1e7 within 1200 cycles at TSSFAC
// 0.85 and 1e10 at 0.88, and lost 45 % of its energy unbooked at 0.9, where the same runs at the
// step held fixed conserve it (tests/core/test_step_modulation.cpp); free blocks and one-element
// cantilevers gained energy at TSSFAC 0.9 this way. Held, Q can fall by only 0.35 % over the
// >= 3.5 cycles of the fastest mode's period at TSSFAC 0.9 (omega dt <= 1.8), so the step's
// modulation is ~0.02 % instead of 5.8 %. Safety is kept: the held Q is never below this cycle's, so
// the step never exceeds the damped-oscillator limit (2/omega)(sqrt(1 + xi^2) - xi); geometry
// (L, c) still acts at once. Cost: after compressing once an element keeps (most of) its Q2 term
// (Q decays by e in 1000 cycles), so a vibrating body runs at the compressing step throughout.
inline double step_q(double L, double c, double trD, double q1, double q2, double q_held) {
  const double Q = trD < 0 ? q2 * c + q1 * L * (-trD) : 0.0;
  const double held = (1 - kStepQDecay) * q_held;
  return Q > held ? Q : held;
}

// Artificial bulk viscosity pressure (compression only), LS-DYNA default form
// q = rho l (Q1 l trD^2 - Q2 c trD), but with the step's characteristic length l = L = V / A_max
// where the LS-DYNA Theory Manual has l = V^(1/3); the two agree for a cube. Why: on
// the element's thickness mode (omega = 2c/L) q is an explicit damper of ratio
// xi = (l/L)(Q2 + Q1 l |trD| / c), and the step above is stable only for l = L. With l = V^(1/3) a
// flat element (aspect A, l/L = A^(2/3)) is damped far harder than the step allows: the Hertz
// block's 10.8 x 10.8 x 0.083 mm corner elements had l/L = 25.6, xi = 1.54, a limit of 0.30 L/c,
// and blew up at TSSFAC 0.8-0.9 (tests/core/test_bulk_viscosity_step.cpp).
// c is the step's wave speed for the same reason: a ply element steps at its thickness wave
// (directional_step.hpp), 3.6x slower than its fibre wave, and with the fibre wave here its
// thickness mode would be damped at 3.6 Q2 (xi = 0.22 at Q2 = 0.06) instead of Q2; step_q takes the
// same c, so the step stays that mode's damped limit.
inline double bulk_viscosity(double rho, double L, double c, double trD, double q1, double q2) {
  if (trD >= 0) return 0.0;
  return rho * L * (q1 * L * trD * trD - q2 * c * trD);
}

// The first (lowest id) element with a non-positive volume or a non-finite result.
inline void record_bad(ChunkResult& r, Index id, double volume, bool nan) {
  if (r.bad_element < 0 || id < r.bad_element) {
    r.bad_element = id;
    r.bad_volume = volume;
    r.bad_is_nan = nan;
  }
}

// The smallest element step (ties: lowest id, so the result does not depend on the chunking).
inline void record_dt(ChunkResult& r, Index id, double dte) {
  if (dte < r.dt_min || (dte == r.dt_min && id < r.dt_element)) {
    r.dt_min = dte;
    r.dt_element = id;
  }
}

}  // namespace plyimpact::solver
