// Kernels for the 8-node hexahedron: centre Jacobian, Flanagan-Belytschko uniform gradient, volume,
// characteristic length, 2x2x2 Gauss gradients and the hourglass base vectors. The one-point
// element pass uses their lane versions (hex8_lanes.hpp, with the one-point gradient and the
// hourglass shape vectors). Local arrays are component-major, x[i][k] = coordinate i of local
// node k, so the loops over the 8 nodes vectorise. Node order is LS-DYNA's (= VTK_HEXAHEDRON =
// gmsh): nodes 0-3 on zeta = -1 counter-clockwise, 4-7 above them. References: Flanagan &
// Belytschko, IJNME 17 (1981) 679-706 (FB81); LS-DYNA Theory Manual, "Solid Elements" and
// "Hourglass Control".
#pragma once

namespace plyimpact::element {

inline constexpr double kXi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
inline constexpr double kEta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
inline constexpr double kZeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};

// Hourglass base vectors Gamma_alpha (LS-DYNA Theory Manual table; xi*eta, eta*zeta, zeta*xi,
// xi*eta*zeta patterns). Each is orthogonal to the constant vector and to xi, eta, zeta.
inline constexpr double kGamma[4][8] = {
    {1, -1, 1, -1, 1, -1, 1, -1},
    {1, 1, -1, -1, -1, -1, 1, 1},
    {1, -1, -1, 1, -1, 1, 1, -1},
    {1, -1, 1, -1, -1, 1, -1, 1},
};

using NodeVec = double[3][8];  // component-major nodal values of one element

// Jacobian at the element centre of any nodal field u: J[3a+c] = du_a/dxi_c = sum_k u_a,k xi_c,k / 8.
// With u = x it is dx/dxi; with u = v it is dv/dxi, and L = dv/dx = J_v J_x^-1.
inline void hex8_centroid_jacobian(const NodeVec& u, double J[9]) noexcept;

// Mid-step velocity gradient L = J_v (J_x - dt/2 J_v)^-1 from the end-of-step Jacobian J_x and the
// velocity Jacobian J_v: the geometry x^{n+1/2} = x^{n+1} - dt/2 v^{n+1/2}. For a rigid rotation
// this L is exactly skew (a Cayley transform), so no spurious strain arises (second-order
// accurate strain increments, as in DYNA3D/LULESH). Returns false if the mid-step Jacobian is singular.
inline bool mid_step_velocity_gradient(const double Jx[9], const double Jv[9], double dt, double L[9]) noexcept;
// The same, giving also the mid-step Jacobian Jm and its inverse.
inline bool mid_step_velocity_gradient(const double Jx[9], const double Jv[9], double dt, double L[9], double Jm[9],
                                       double Jm_inv[9]) noexcept;

// Flanagan-Belytschko uniform (mean) gradient b_k = (1/V) dV/dx_k and the exact volume
// V = (1/3) sum_k x_k . dV/dx_k (exact for any trilinear hexahedron). Returns V.
inline double hex8_mean_gradient(const NodeVec& x, NodeVec& b) noexcept;

// Exact volume only (same as hex8_mean_gradient's return value).
inline double hex8_volume(const NodeVec& x) noexcept;

// Largest face area of the element; faces of a warped hexahedron use |d1 x d2|/2 with the face
// diagonals (LS-DYNA's characteristic length is volume / largest face area).
inline double hex8_max_face_area(const NodeVec& x) noexcept;

// Jacobian determinant at each of the 8 corners (the triple product of the three edges leaving the
// corner, scaled to the reference cube). All must be > 0 for a valid element.
inline void hex8_corner_jacobians(const NodeVec& x, double detj[8]) noexcept;

// 2x2x2 Gauss point data for ELFORM 2: gradients B[g][i][k] and det J[g] (weights are 1).
// Returns false if any det J <= 0.
// J (optional, may be nullptr) receives the Jacobians dx/dxi at the points, row-major.
inline bool hex8_gauss_gradients(const NodeVec& x, double B[8][3][8], double detj[8], double (*J)[9] = nullptr,
                                 double (*Jinv)[9] = nullptr) noexcept;

// Velocity Jacobian dv/dxi at Gauss point gp (same point order as hex8_gauss_gradients).
inline void hex8_gauss_jacobian(const NodeVec& v, int gp, double J[9]) noexcept;

// Small dense helpers on row-major 3x3 matrices.
inline double det3(const double a[9]) noexcept;
// Inverse of a; returns the determinant (the inverse is not written if it is 0).
inline double inverse3(const double a[9], double inv[9]) noexcept;

}  // namespace plyimpact::element

#include "element/hex8_kernels.hpp"
