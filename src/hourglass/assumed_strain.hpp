// Moduli of the assumed-strain hourglass control IHQ 6 (Belytschko & Bindeman, "Assumed strain
// stabilization of the eight node hexahedral element", CMAME 105 (1993) 225-260; LS-DYNA theory
// manual, hourglass control IHQ 6): the lane force update of the one-point element pass, and,
// once per element at t = 0, the elastic moduli its hourglass strains are multiplied with.
//
// Our choice (per-mode moduli, documented in docs/theory.md section 6): every
// hourglass strain component of the element frame (x', y', z' = the orthonormalised centre-Jacobian
// columns, see element_frame) gets the modulus of a uniaxial stress along that axis (normal
// components: E(n) = 1 / (n n : S : n n)) or of pure shear in that plane (shear components:
// G(n, m) = 1 / (4 n m : S : n m)), from the material's compliance S in its own axes. The
// hourglass field cannot represent the lateral strains of a bent fibre (they vary quadratically),
// so a uniaxial modulus is what makes a rectangular element bend exactly like an Euler-Bernoulli
// beam of that fibre direction; for an isotropic material E(n) = E and G(n, m) = G. The frame turns
// with the element and so does a ply's material frame, so the moduli are fixed at t = 0.
// A *MAT_054 element starts from its undamaged moduli; once its material loses an in-plane
// component (material::composite_damage_lost_components) the element's moduli are those of the
// degraded compliance and its stored forces follow (degrade_assumed_strain), so the hourglass modes
// of a failed element are no stiffer than its constant-strain part.
#pragma once

#include <cmath>
#include <vector>

#include "core/lanes.hpp"
#include "model/model.hpp"

namespace plyimpact::hourglass {

// Orthonormal element frame (rows e1, e2, e3, global components) and the projected half-lengths
// (a, b, c) from the centre Jacobian J[3i+c] = dx_i/dxi_c: Gram-Schmidt of the xi, eta columns
// (a QR decomposition, so 8 a b c = 8 det J = the one-point volume). Lane l of lane-major arrays,
// so the element kernel's SIMD lane loop can call it (N = 1 for a single element); straight-line
// scalar code, which GCC vectorises across the lanes.
template <int N>
PLYIMPACT_LANE_KERNEL void element_frame(const double (&J)[9][N], int l, double (&E)[9][N], double (&a)[N], double (&b)[N],
                          double (&c)[N]) {
  const double c0x = J[0][l], c0y = J[3][l], c0z = J[6][l];
  const double c1x = J[1][l], c1y = J[4][l], c1z = J[7][l];
  const double len0 = std::sqrt(c0x * c0x + c0y * c0y + c0z * c0z), ra = 1.0 / len0;
  const double e1x = c0x * ra, e1y = c0y * ra, e1z = c0z * ra;
  const double p = e1x * c1x + e1y * c1y + e1z * c1z;
  const double ux = c1x - p * e1x, uy = c1y - p * e1y, uz = c1z - p * e1z;
  const double len1 = std::sqrt(ux * ux + uy * uy + uz * uz), rb = 1.0 / len1;
  const double e2x = ux * rb, e2y = uy * rb, e2z = uz * rb;
  const double e3x = e1y * e2z - e1z * e2y, e3y = e1z * e2x - e1x * e2z, e3z = e1x * e2y - e1y * e2x;
  E[0][l] = e1x, E[1][l] = e1y, E[2][l] = e1z;
  E[3][l] = e2x, E[4][l] = e2y, E[5][l] = e2z;
  E[6][l] = e3x, E[7][l] = e3y, E[8][l] = e3z;
  a[l] = len0, b[l] = len1, c[l] = e3x * J[2][l] + e3y * J[5][l] + e3z * J[8][l];
}

// (num_elements, 6) moduli per element: E_x', E_y', E_z', G_x'y', G_y'z', G_z'x' (Pa), from the
// reference geometry. Throws std::logic_error for a material without elastic constants (rigid).
std::vector<double> assumed_strain_moduli(const model::Model& model, const model::ElementBlock& block);

// The six moduli of element e (as assumed_strain_moduli) when its material has lost the in-plane
// components `lost` (material::lost_component mask; 0: undamaged). A lost normal component keeps
// no Poisson coupling and kLostComponentResidual of its compliance's stiffness, a lost ab shear
// kLostComponentResidual of GAB (the degradation table's E = 0, nu = 0, G = 0, with a floor so that
// no hourglass mode of a failed element is entirely free).
inline constexpr double kLostComponentResidual = 1e-3;
void assumed_strain_element_moduli(const model::Model& model, const model::ElementBlock& block, std::size_t e,
                                   int lost, double (&m)[6]);

// Rescales the stored forces Q (12, element frame, Q[4 i + alpha] as Qp) of an element whose
// moduli change from m_old to m_new: every accumulated force is its modulus times an accumulated
// amplitude, so it follows the modulus (secant, as the material's stress drops with its stiffness).
// The normal modes take their axis's E ratio. The three shear-coupled forces are
// Q_x1 = Sxy/b + Szx/c, Q_y2 = Sxy/a + Syz/c, Q_z0 = Syz/b + Szx/a in generalised shear forces S
// (a map of determinant 2/(abc)); they are split with the current half-lengths a, b, c, scaled with
// their shear modulus' ratio and recombined.
void rescale_assumed_strain_forces(double (&Q)[12], const double (&m_old)[6], const double (&m_new)[6], double a,
                                   double b, double c);

// Forces of the assumed-strain stabilisation for kLanes elements. In the co-rotational element
// frame x' y' z' (element_frame: orthonormalised centre-Jacobian columns, half-lengths a b c).
// Hourglass displacement u_i = sum_alpha q_i,alpha h_alpha with h = (xi eta, eta zeta, zeta xi,
// xi eta zeta) for alpha = 0..3 (the kGamma rows); with gamma . Gamma = 8 the amplitude rate is
// q' = g'/8 and the generalised force is Q = P/8, P = dW/dq. Assumed hourglass strains (our
// derivation of the 3-D field, B&B's principle): every normal strain is kept, e.g.
// eps_x'x' = (q_x,2 zeta + q_x,0 eta + q_x,3 eta zeta) / a; of the shear strains only the parts
// linear in the third coordinate are kept,
//   gamma_x'y' = zeta (q_x,1 / b + q_y,2 / a), gamma_y'z' = xi (q_y,2 / c + q_z,0 / b),
//   gamma_z'x' = eta (q_z,0 / a + q_x,1 / c)
// (twist, which a plate really carries); the others, e.g. xi q_x,2 / c in gamma_z'x' of a bent
// thin element, are the parasitic shear that locks bending and are dropped. All 12 modes keep
// stiffness (the three shear-coupled ones form a positive definite 3x3 block). Integrated over the
// element (mean of zeta^2: 1/3, of (eta zeta)^2: 1/9) with the per-mode moduli Hm (see above)
// this gives W = sum QM V/6 [E (q/a)^2 for the linear terms, E/3 (q/a)^2 for xi eta zeta,
// G (shear)^2], exact pure bending of a rectangular element. (Sources: Belytschko & Bindeman 1993;
// Belytschko, Liu & Moran, Nonlinear Finite Elements, sec. 8.7; code_aster R3.06.11.)
// Forces are accumulated in the element frame (Qa + increment -> Qp, stored), so a rigid rotation
// carries them exactly; Qs are the forces the nodes received last cycle (Qa = Qs unless the element's
// moduli just changed: rescale_assumed_strain_forces); Qh = E^T Qp are the global forces, dHG their
// work (trapezoid rule: Qs and Qp), dHG_old its half with the previous cycle's forces.
PLYIMPACT_LANE_KERNEL void assumed_strain_forces_lanes(double qm, const LaneVec<6>& Hm, const LaneVec<9>& Jx, const LaneScalar& V,
                                        const double (&g)[3][4][kLanes], const LaneVec<12>& Qs,
                                        const LaneVec<12>& Qa, double dt,
                                        double (&Qp)[3][4][kLanes], double (&Qh)[3][4][kLanes], LaneScalar& dHG,
                                        LaneScalar& dHG_old) {
  alignas(64) double Ef[9][kLanes], ha[kLanes], hb[kLanes], hc[kLanes];
  PLYIMPACT_LANES element_frame(Jx, l, Ef, ha, hb, hc);
  alignas(64) double gp[3][4][kLanes];  // g in the element frame
  for (int j = 0; j < 3; ++j)
    for (int a = 0; a < 4; ++a)
      PLYIMPACT_LANES gp[j][a][l] = Ef[3 * j][l] * g[0][a][l] + Ef[3 * j + 1][l] * g[1][a][l] + Ef[3 * j + 2][l] * g[2][a][l];
  PLYIMPACT_LANES {
    // Amplitude increments d = g' dt / 8; force increments dQ' = dP'/8 = k (...), k = QM V / 24.
    const double d8 = 0.125 * dt, k = qm * V[l] * (1.0 / 24.0);
    const double ia = 1.0 / ha[l], ib = 1.0 / hb[l], ic = 1.0 / hc[l];
    const double kx = k * Hm[0][l] * ia * ia, ky = k * Hm[1][l] * ib * ib, kz = k * Hm[2][l] * ic * ic;
    const double dx1 = gp[0][1][l] * d8, dy2 = gp[1][2][l] * d8, dz0 = gp[2][0][l] * d8;
    const double sxy = dx1 * ib + dy2 * ia, syz = dy2 * ic + dz0 * ib, szx = dz0 * ia + dx1 * ic;
    const double gxy = k * Hm[3][l] * sxy, gyz = k * Hm[4][l] * syz, gzx = k * Hm[5][l] * szx;
    Qp[0][0][l] = Qa[0][l] + kx * gp[0][0][l] * d8;
    Qp[0][1][l] = Qa[1][l] + gxy * ib + gzx * ic;
    Qp[0][2][l] = Qa[2][l] + kx * gp[0][2][l] * d8;
    Qp[0][3][l] = Qa[3][l] + (1.0 / 3.0) * kx * gp[0][3][l] * d8;
    Qp[1][0][l] = Qa[4][l] + ky * gp[1][0][l] * d8;
    Qp[1][1][l] = Qa[5][l] + ky * gp[1][1][l] * d8;
    Qp[1][2][l] = Qa[6][l] + gxy * ia + gyz * ic;
    Qp[1][3][l] = Qa[7][l] + (1.0 / 3.0) * ky * gp[1][3][l] * d8;
    Qp[2][0][l] = Qa[8][l] + gyz * ib + gzx * ia;
    Qp[2][1][l] = Qa[9][l] + kz * gp[2][1][l] * d8;
    Qp[2][2][l] = Qa[10][l] + kz * gp[2][2][l] * d8;
    Qp[2][3][l] = Qa[11][l] + (1.0 / 3.0) * kz * gp[2][3][l] * d8;
    double e_old = 0, e_new = 0;  // trapezoid rule, as IHQ 4/5 (the power Q . g is frame invariant)
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 4; ++a) {
        e_old += 0.5 * Qs[4 * j + a][l] * gp[j][a][l] * dt;
        e_new += 0.5 * Qp[j][a][l] * gp[j][a][l] * dt;
      }
    dHG_old[l] = e_old;
    dHG[l] = e_old + e_new;
  }
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 4; ++a)
      PLYIMPACT_LANES Qh[i][a][l] = Ef[i][l] * Qp[0][a][l] + Ef[3 + i][l] * Qp[1][a][l] + Ef[6 + i][l] * Qp[2][a][l];
}

}  // namespace plyimpact::hourglass
