// Stiffness hourglass control, IHQ 4 and 5 (Flanagan & Belytschko 1981; LS-DYNA Theory Manual,
// "Hourglass Control"): generalised hourglass forces accumulated from hourglass strain increments
// and rotated with the element (the incremental rotation R of the stress update); IHQ 5 differs
// from IHQ 4 only by the exact mean gradient behind gamma (element/hex8_lanes.hpp).
#pragma once

#include <vector>

#include "core/lanes.hpp"
#include "element/hex8_lanes.hpp"
#include "model/model.hpp"

namespace plyimpact::hourglass {

// Stiffness scaled with the element's maximum frequency as in FB81: k = QM M V sum(b_ik^2) / 4
// (keeps omega_hg dt < 2 for QM up to about 0.2 at TSSFAC 0.9). FB81 take M = rho c^2 = lambda + 2 mu
// of an isotropic material. For an anisotropic one the largest frequency is not the fastest
// wave's over every direction of the element: sum b^2 ~ sum_j 1/h_j^2 gathers the element's
// directions j, and the wave that crosses the element along e_j has its own modulus M_j. So
//   M = sum_j M_j w_j / sum_j w_j,  w_j = sum_k (e_j . b_k)^2,
// M_j = rho c^2 of the fastest wave along the element axis e_j (largest eigenvalue of the acoustic
// tensor C_ijkl e_j e_l); lambda + 2 mu for an isotropic material, whatever the shape. A thin ply's
// sum b^2 is its thickness term, so its M is the through-thickness modulus (about 12 GPa for
// T800S/M21), not the fibre's (160 GPa) that the stable step uses. Per element, from the reference
// geometry (the element frame and a ply's axes turn together); stiffness_hourglass_moduli.
std::vector<double> stiffness_hourglass_moduli(const model::Model& model, const model::ElementBlock& block);

// Qs: accumulated forces of the previous cycle (global axes, [4 i + a]); Qh: updated ones; dHG:
// their work over the step (trapezoid rule between the rotated old and the new force), dHG_old its
// half with the rotated old force. M: the
// elements' moduli (stiffness_hourglass_moduli).
PLYIMPACT_LANE_KERNEL void stiffness_forces_lanes(double qm, const LaneScalar& M, const element::LaneNodeVec& b, const LaneScalar& V,
                                   const LaneVec<9>& R, const double (&g)[3][4][kLanes], const LaneVec<12>& Qs,
                                   double dt, double (&Qh)[3][4][kLanes], LaneScalar& dHG, LaneScalar& dHG_old) {
  PLYIMPACT_LANES {
    double bb = 0;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) bb += b[i][k][l] * b[i][k][l];
    const double kh = 0.25 * qm * M[l] * V[l] * bb;
    double e_old = 0, e_new = 0;
    for (int a = 0; a < 4; ++a) {
      const double q0 = Qs[a][l], q1r = Qs[4 + a][l], q2r = Qs[8 + a][l];
      for (int i = 0; i < 3; ++i) {
        const double rotated = R[3 * i][l] * q0 + R[3 * i + 1][l] * q1r + R[3 * i + 2][l] * q2r;
        const double updated = rotated + kh * g[i][a][l] * dt;
        e_old += 0.5 * rotated * g[i][a][l] * dt;
        e_new += 0.5 * updated * g[i][a][l] * dt;
        Qh[i][a][l] = updated;
      }
    }
    dHG_old[l] = e_old;
    dHG[l] = e_old + e_new;
  }
}

}  // namespace plyimpact::hourglass
