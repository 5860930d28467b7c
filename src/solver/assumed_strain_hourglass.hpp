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

#include "model/model.hpp"

namespace plyimpact::solver {

// Orthonormal element frame (rows e1, e2, e3, global components) and the projected half-lengths
// (a, b, c) from the centre Jacobian J[3i+c] = dx_i/dxi_c: Gram-Schmidt of the xi, eta columns
// (a QR decomposition, so 8 a b c = 8 det J = the one-point volume).
void element_frame(const double J[9], double E[9], double half[3]);

// (num_elements, 6) moduli per element: E_x', E_y', E_z', G_x'y', G_y'z', G_z'x' (Pa), from the
// reference geometry. Throws std::logic_error for a material without elastic constants (rigid).
std::vector<double> assumed_strain_moduli(const model::Model& model, const model::ElementBlock& block);

}  // namespace plyimpact::solver
