// Elastic constitutive data: *MAT_001 (isotropic) and *MAT_002 (orthotropic) stiffness matrices,
// the admissibility check of the orthotropic constants, the stable-step wave modulus and the
// material axes (AOPT 0, 2, 3 + BETA). Voigt order is LS-DYNA's: xx, yy, zz, xy, yz, zx (material
// axes: aa, bb, cc, ab, bc, ca) with engineering shear strains. Units SI.
#pragma once

#include <array>
#include <string>

#include "config/scene.hpp"
#include "core/types.hpp"

namespace plyimpact::material {

using Stiffness6 = std::array<double, 36>;  // row-major 6x6, sigma = C * strain (engineering shear)

// Lame constants of *MAT_001.
struct IsotropicConstants {
  double lambda = 0, mu = 0, bulk = 0;
};
IsotropicConstants isotropic_constants(const config::MatElastic& m);

// Stiffness of *MAT_002 in its material axes (a, b, c). PRBA, PRCA, PRCB are the LS-DYNA minor
// ratios nu_ba, nu_ca, nu_cb. Throws InputError (naming `where`) when the compliance is not
// positive definite, with the offending combination and a hint about the PRBA convention.
Stiffness6 orthotropic_stiffness(const config::MatOrthotropicElastic& m, const config::SourceLocation& where);

// The same stiffness expressed in global axes: Q has the unit material axes a, b, c as rows (global
// components), so strain_material = Q strain Q^T.
Stiffness6 rotate_to_global(const Stiffness6& c_material, const Mat3& q);

// Largest rho*c^2 over all propagation directions n: the largest eigenvalue of the acoustic tensor
// A_ik = C_ijkl n_j n_l, maximised over the unit sphere. It is the exact P-wave modulus for an
// isotropic material (lambda + 2 mu) and, for an orthotropic one, bounds the phase speed in every
// direction (found by a dense sphere sampling refined by local search to 1e-10 relative).
double max_wave_modulus(const Stiffness6& c);

// Material axes of one element as rows a, b, c of a rotation matrix.
//   AOPT 0: a along nodes 1->2, b in the plane of nodes 1, 2, 4; AOPT 2: global vectors A, D
//   (c = a x d, b = c x a); AOPT 3: c = mid-surface normal, a = V x c, b = c x a.
// The axes are then rotated about c by `beta` (rad). x_ref: component-major reference coordinates.
Mat3 material_axes(const config::MaterialAxes& axes, double beta, const double x_ref[3][8]);

}  // namespace plyimpact::material
