// Moduli of the assumed-strain hourglass control IHQ 6 (Belytschko & Bindeman, "Assumed strain
// stabilization of the eight node hexahedral element", CMAME 105 (1993) 225-260; LS-DYNA theory
// manual, hourglass control IHQ 6). The stabilisation itself is in element_update.cpp (elform1);
// here, once per element at t = 0, the elastic moduli its hourglass strains are multiplied with.
//
// Our choice (per-mode moduli, documented in README "Hourglass control on thin plies"): every
// hourglass strain component of the element frame (x', y', z' = the orthonormalised centre-Jacobian
// columns, see element_frame) gets the modulus of a uniaxial stress along that axis (normal
// components: E(n) = 1 / (n n : S : n n)) or of pure shear in that plane (shear components:
// G(n, m) = 1 / (4 n m : S : n m)), from the material's compliance S in its own axes. The
// hourglass field cannot represent the lateral strains of a bent fibre (they vary quadratically),
// so a uniaxial modulus is what makes a rectangular element bend exactly like an Euler-Bernoulli
// beam of that fibre direction; for an isotropic material E(n) = E and G(n, m) = G. The frame turns
// with the element and so does a ply's material frame, so the moduli are fixed at t = 0.
// Undamaged moduli are used for *MAT_054 (as LS-DYNA takes the elastic constants of the card).
#pragma once

#include <vector>

#include <cmath>

#include "model/model.hpp"

namespace plyimpact::solver {

// Orthonormal element frame (rows e1, e2, e3, global components) and the projected half-lengths
// (a, b, c) from the centre Jacobian J[3i+c] = dx_i/dxi_c: Gram-Schmidt of the xi, eta columns
// (a QR decomposition, so 8 a b c = 8 det J = the one-point volume). Lane l of lane-major arrays,
// so the element kernel's SIMD lane loop can call it (N = 1 for a single element); straight-line
// scalar code, which GCC vectorises across the lanes.
template <int N>
inline void element_frame(const double (&J)[9][N], int l, double (&E)[9][N], double (&a)[N], double (&b)[N],
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

}  // namespace plyimpact::solver
