// Point kinematics shared by the element families and the incremental material updates: velocity
// gradient from nodal velocities and gradients, its split into rate of deformation and spin, and
// the Hughes-Winget incremental rotation. Conventions: b[i][k] = dN_k/dx_i; L_ij = dv_i/dx_j;
// D in tensor Voigt order xx yy zz xy yz zx; 3x3 matrices row-major.
#pragma once

namespace plyimpact::element {

// R = (I - dt/2 W)^-1 (I + dt/2 W) for a skew W, in closed form: with Omega = dt/2 W and its axial
// vector w, R = I + 2 (Omega + Omega^2) / (1 + |w|^2) (the Cayley transform; no matrix inverse).
// R is exactly orthogonal, so a rigid rotation carries a stress along to round-off (a Jaumann rate
// would only do so to first order in dt).
inline void hughes_winget(const double W[9], double dt, double R[9]) {
  const double h = 0.5 * dt;
  const double w1 = h * W[7], w2 = h * W[2], w3 = h * W[3];
  const double ww = w1 * w1 + w2 * w2 + w3 * w3;
  const double c = 2.0 / (1.0 + ww);
  // Omega + Omega^2 = Omega + w w^T - |w|^2 I
  R[0] = 1 + c * (w1 * w1 - ww);
  R[1] = c * (-w3 + w1 * w2);
  R[2] = c * (w2 + w1 * w3);
  R[3] = c * (w3 + w2 * w1);
  R[4] = 1 + c * (w2 * w2 - ww);
  R[5] = c * (-w1 + w2 * w3);
  R[6] = c * (-w2 + w3 * w1);
  R[7] = c * (w1 + w3 * w2);
  R[8] = 1 + c * (w3 * w3 - ww);
}

// L[3i+j] = sum_k v[i][k] b[j][k] (with v = X and b the current gradients: F^-1).
inline void velocity_gradient(const double v[3][8], const double b[3][8], double L[9]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 8; ++k) s += v[i][k] * b[j][k];
      L[3 * i + j] = s;
    }
}

// D = (L + L^T)/2 (tensor Voigt), W = (L - L^T)/2.
inline void split_rate(const double L[9], double D[6], double W[9]) {
  D[0] = L[0];
  D[1] = L[4];
  D[2] = L[8];
  D[3] = 0.5 * (L[1] + L[3]);
  D[4] = 0.5 * (L[5] + L[7]);
  D[5] = 0.5 * (L[6] + L[2]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) W[3 * i + j] = 0.5 * (L[3 * i + j] - L[3 * j + i]);
}

// sigma : D with Voigt stress and tensor-Voigt D.
inline double stress_power(const double s[6], const double D[6]) {
  return s[0] * D[0] + s[1] * D[1] + s[2] * D[2] + 2 * (s[3] * D[3] + s[4] * D[4] + s[5] * D[5]);
}

}  // namespace plyimpact::element
