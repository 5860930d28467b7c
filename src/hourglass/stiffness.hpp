// Stiffness hourglass control, IHQ 4 and 5 (Flanagan & Belytschko 1981; LS-DYNA Theory Manual,
// "Hourglass Control"): generalised hourglass forces accumulated from hourglass strain increments
// and rotated with the element (the incremental rotation R of the stress update); IHQ 5 differs
// from IHQ 4 only by the exact mean gradient behind gamma (element/hex8_lanes.hpp).
#pragma once

#include "core/lanes.hpp"
#include "element/hex8_lanes.hpp"

namespace plyimpact::hourglass {

// Stiffness scaled with the element's maximum frequency as in FB81:
// k = QM rho c^2 V sum(b_ik^2) / 4 (keeps omega_hg dt < 2 for QM up to about 0.2 at TSSFAC 0.9).
// Qs: accumulated forces of the previous cycle (global axes, [4 i + a]); Qh: updated ones; dHG:
// their work over the step (trapezoid rule between the rotated old and the new force).
PLYIMPACT_LANE_KERNEL void stiffness_forces_lanes(double qm, double rho_c2, const element::LaneNodeVec& b, const LaneScalar& V,
                                   const LaneVec<9>& R, const double (&g)[3][4][kLanes], const LaneVec<12>& Qs,
                                   double dt, double (&Qh)[3][4][kLanes], LaneScalar& dHG) {
  PLYIMPACT_LANES {
    double bb = 0;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) bb += b[i][k][l] * b[i][k][l];
    const double kh = 0.25 * qm * rho_c2 * V[l] * bb;
    double e = 0;
    for (int a = 0; a < 4; ++a) {
      const double q0 = Qs[a][l], q1r = Qs[4 + a][l], q2r = Qs[8 + a][l];
      for (int i = 0; i < 3; ++i) {
        const double rotated = R[3 * i][l] * q0 + R[3 * i + 1][l] * q1r + R[3 * i + 2][l] * q2r;
        const double updated = rotated + kh * g[i][a][l] * dt;
        e += 0.5 * (rotated + updated) * g[i][a][l] * dt;
        Qh[i][a][l] = updated;
      }
    }
    dHG[l] = e;
  }
}

}  // namespace plyimpact::hourglass
