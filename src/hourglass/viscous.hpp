// Viscous hourglass control, IHQ 1-3 (Flanagan & Belytschko, IJNME 17 (1981) 679-706; LS-DYNA
// Theory Manual, "Hourglass Control"): Q_ia = a_h g_ia with a_h = QM rho V^(2/3) c / 4 and the
// hourglass rates g = v . gamma. IHQ 1 uses the bare base vectors Gamma, IHQ 2 and 3 the projected
// gamma (element/hex8_lanes.hpp, hex8_hourglass_lanes); the force law is the same.
#pragma once

#include "core/lanes.hpp"

namespace plyimpact::hourglass {

// Qs: the forces of the previous cycle (stored, [4 i + a]); Qh: this cycle's; dHG: their work over
// the step with the trapezoid rule (previous and new force), like the stress work: the force of a
// cycle acts over both half steps around it. dHG_old: the half with the previous cycle's forces.
PLYIMPACT_LANE_KERNEL void viscous_forces_lanes(double qm, double c, const LaneScalar& rho, const LaneScalar& cbrtV,
                                 const double (&g)[3][4][kLanes], const LaneVec<12>& Qs, double dt,
                                 double (&Qh)[3][4][kLanes], LaneScalar& dHG, LaneScalar& dHG_old) {
  alignas(64) double ah[kLanes];
  PLYIMPACT_LANES ah[l] = 0.25 * qm * rho[l] * cbrtV[l] * cbrtV[l] * c;
  PLYIMPACT_LANES {
    double e_old = 0, e_new = 0;
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 4; ++a) {
        Qh[i][a][l] = ah[l] * g[i][a][l];
        e_old += 0.5 * Qs[4 * i + a][l] * g[i][a][l] * dt;
        e_new += 0.5 * Qh[i][a][l] * g[i][a][l] * dt;
      }
    dHG_old[l] = e_old;
    dHG[l] = e_old + e_new;
  }
}

}  // namespace plyimpact::hourglass
