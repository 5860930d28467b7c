// Elastic constitutive data: *MAT_001 (isotropic) and *MAT_002 (orthotropic) stiffness matrices,
// the admissibility test of the orthotropic constants, the stable-step wave modulus and the
// material axes (AOPT 0, 2, 3 + BETA). Plain constants in, no input types: the conversion from the
// cards (and the error messages that name them) is model/material_builder's. Voigt order is LS-DYNA's: xx, yy, zz, xy, yz, zx (material
// axes: aa, bb, cc, ab, bc, ca) with engineering shear strains. Units SI.
#pragma once

#include <array>
#include <string>

#include "core/types.hpp"

namespace plyimpact::material {

using Stiffness6 = std::array<double, 36>;  // row-major 6x6, sigma = C * strain (engineering shear)

// Lame constants of *MAT_001 from Young's modulus E and Poisson's ratio PR.
struct IsotropicConstants {
  double lambda = 0, mu = 0, bulk = 0;
};
IsotropicConstants isotropic_constants(double E, double PR);

// Orthotropic elastic constants as on the *MAT_002 / *MAT_054 cards (Pa). PRBA, PRCA, PRCB are the
// LS-DYNA minor ratios nu_ba, nu_ca, nu_cb.
struct OrthotropicConstants {
  double EA = 0, EB = 0, EC = 0, PRBA = 0, PRCA = 0, PRCB = 0, GAB = 0, GBC = 0, GCA = 0;
};

// 1 - nu_ab nu_ba - nu_bc nu_cb - nu_ca nu_ac - 2 nu_ba nu_cb nu_ac: with positive moduli the
// compliance is positive definite iff this and the smallest eigenvalue of the compliance are
// positive (Lempriere 1968); admissible() checks both.
double orthotropic_determinant(const OrthotropicConstants& m);
bool admissible(const OrthotropicConstants& m);

// Stiffness in the material axes (a, b, c): the inverse of the card's compliance. Call only for
// admissible constants.
Stiffness6 orthotropic_stiffness(const OrthotropicConstants& m);

// The per-element orientation of an anisotropic material: axes and the stiffness rotated to
// global (reference) axes.
struct Orientation {
  Mat3 axes{};                  // rows a, b, c (global components)
  Stiffness6 c_global{};
};

// The same stiffness expressed in global axes: Q has the unit material axes a, b, c as rows (global
// components), so strain_material = Q strain Q^T.
Stiffness6 rotate_to_global(const Stiffness6& c_material, const Mat3& q);

// Largest rho*c^2 over all propagation directions n: the largest eigenvalue of the acoustic tensor
// A_ik = C_ijkl n_j n_l, maximised over the unit sphere. It is the exact P-wave modulus for an
// isotropic material (lambda + 2 mu) and, for an orthotropic one, bounds the phase speed in every
// direction (found by a dense sphere sampling refined by local search to 1e-10 relative).
double max_wave_modulus(const Stiffness6& c);

// How the material axes of an element are found (the AOPT options of the LS-DYNA cards).
struct MaterialAxes {
  int AOPT = 0;      // 0: element nodes 1-2-4; 2: global vectors A, D; 3: V x mid-surface normal
  Vec3 A{1, 0, 0};   // AOPT 2
  Vec3 D{0, 1, 0};   // AOPT 2
  Vec3 V{1, 0, 0};   // AOPT 3
  double BETA = 0;   // rad, rotation of a and b about c (MANGLE / BETA on the card, AOPT 3)
};

// Material axes of one element as rows a, b, c of a rotation matrix.
//   AOPT 0: a along nodes 1->2, b in the plane of nodes 1, 2, 4; AOPT 2: global vectors A, D
//   (c = a x d, b = c x a); AOPT 3: c = mid-surface normal, a = V x c, b = c x a.
// The axes are then rotated about c by `beta` (rad). x_ref: component-major reference coordinates.
Mat3 material_axes(const MaterialAxes& axes, double beta, const double x_ref[3][8]);

}  // namespace plyimpact::material
