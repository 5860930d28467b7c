// Stable step of an anisotropic one-point hexahedron from its own stiffness instead of the fastest
// wave of its material.
//
// The element step L / c (element_step.hpp) takes c from the material's fastest wave in any
// direction (a ply's fibre wave, ~10 km/s) and L = V / A_max from the element's thinnest direction.
// On a thin ply that pairs the fibre modulus with the through-thickness length: the one-point
// element's fastest constant-strain mode is the thickness mode, whose modulus is the ply's
// transverse C33 (~13 GPa against EA 157 GPa), so the bound is about 3.5x too short.
//
// The exact constant-strain limit: with the lumped node mass m = rho V / 8 and the element
// stiffness K = V B^T C B, omega_max^2 = (8 / rho) lambda_max(C^1/2 A C^1/2), A = sum_k B_k B_k^T
// (6 x 6, from the mean gradients b_k alone). For a rectangular box of an isotropic material it
// gives omega = 2c / L, LS-DYNA's bound; for a cube its dilatational mode is faster (up to
// sqrt(3K / (lambda + 2 mu)) = 1.36x at nu = 0.3), which L / c does not see. So the directional
// speed c_step = L omega_max / 2 replaces c only where it is slower: no isotropic element, and no
// element whose L / c was already the shorter bound, changes its step.
//
// Only ELFORM 1 with IHQ 1-3 or 6: the viscous forms add no stiffness; the assumed-strain form
// (IHQ 6) gives each hourglass mode the strain energy of the bending field it represents, which a
// thin element carries at in-plane wavelengths (slower than its thickness mode; verified by
// tests/core/test_directional_step.cpp, which drives every mode at the computed limit). The
// stiffness forms IHQ 4/5 scale their stiffness with sum b^2, i.e. with the thickness, and keep
// the material's bound.
//
// ELFORM 2 has no hourglass modes to bound separately: its stiffness is the B-bar K = sum_g det J_g
// B_g^T C B_g over the 2x2x2 points, so the exact element limit is omega_max^2 = lambda_max(K) / m
// with m = rho V / 8, one 24 x 24 eigenvalue per element at the start. The element-by-element
// bound (the assembled mesh's largest eigenvalue is at most the largest element's, for lumped
// mass) makes it safe for the mesh. On a thin ply its fastest mode is again the thickness mode:
// the parasitic shear of its bending modes acts over the in-plane lengths.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "element/hex8.hpp"
#include "model/model.hpp"

namespace plyimpact::solver {

// Per element of the block, the wave speed (m/s) its stable step uses: min(c, L omega_max / 2) at
// the reference geometry. Empty when the block keeps the material's wave speed for every element
// (isotropic, IHQ 4/5, rigid, or no element slower than c).
std::vector<double> step_wave_speeds(const model::Model& model, const model::ElementBlock& block);

// omega_max^2 rho / 8 of one element: lambda_max(C^1/2 A C^1/2), Pa/m^2, for the mean gradients b
// (b[i][k] = dN_k/dx_i) in the axes of the stiffness C (Voigt xx yy zz xy yz zx, engineering shear).
double constant_strain_eigenvalue(const std::array<double, 36>& C, const double (&b)[3][8]);

// omega_max^2 rho / 8 of one ELFORM 2 element: lambda_max(K) / V, Pa/m^2, for the nodes x in the
// axes of C; thin >= 0: ELFORM -2 with that thin natural direction (element/hex8_ans.hpp).
double fully_integrated_eigenvalue(const std::array<double, 36>& C, const element::NodeVec& x, int thin = -1);

// The stiffness K of that element (24 x 24, dofs node-major: 3k + component), N/m.
Eigen::Matrix<double, 24, 24> fully_integrated_stiffness(const std::array<double, 36>& C, const element::NodeVec& x,
                                                         int thin = -1);

}  // namespace plyimpact::solver
