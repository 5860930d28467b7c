// Inline definitions of the hex8 kernels declared in hex8.hpp. They live in a header so the
// element pass (another translation unit) inlines and vectorises them: called out of line they
// cost a third of the cycle.
#pragma once

#include <algorithm>
#include <cmath>

namespace plyimpact::element {

inline double det3(const double a[9]) noexcept {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
         a[2] * (a[3] * a[7] - a[4] * a[6]);
}

inline double inverse3(const double a[9], double inv[9]) noexcept {
  const double c00 = a[4] * a[8] - a[5] * a[7];
  const double c01 = a[5] * a[6] - a[3] * a[8];
  const double c02 = a[3] * a[7] - a[4] * a[6];
  const double det = a[0] * c00 + a[1] * c01 + a[2] * c02;
  if (det == 0.0) return 0.0;
  const double r = 1.0 / det;
  inv[0] = c00 * r;
  inv[1] = (a[2] * a[7] - a[1] * a[8]) * r;
  inv[2] = (a[1] * a[5] - a[2] * a[4]) * r;
  inv[3] = c01 * r;
  inv[4] = (a[0] * a[8] - a[2] * a[6]) * r;
  inv[5] = (a[2] * a[3] - a[0] * a[5]) * r;
  inv[6] = c02 * r;
  inv[7] = (a[1] * a[6] - a[0] * a[7]) * r;
  inv[8] = (a[0] * a[4] - a[1] * a[3]) * r;
  return det;
}

inline void hex8_centroid_jacobian(const NodeVec& u, double J[9]) noexcept {
  for (int a = 0; a < 3; ++a) {
    double s0 = 0, s1 = 0, s2 = 0;
    for (int k = 0; k < 8; ++k) {
      s0 += u[a][k] * kXi[k];
      s1 += u[a][k] * kEta[k];
      s2 += u[a][k] * kZeta[k];
    }
    J[3 * a + 0] = 0.125 * s0;
    J[3 * a + 1] = 0.125 * s1;
    J[3 * a + 2] = 0.125 * s2;
  }
}

inline bool mid_step_velocity_gradient(const double Jx[9], const double Jv[9], double dt, double L[9]) noexcept {
  double Jm[9], Jinv[9];
  return mid_step_velocity_gradient(Jx, Jv, dt, L, Jm, Jinv);
}

inline bool mid_step_velocity_gradient(const double Jx[9], const double Jv[9], double dt, double L[9], double Jm[9],
                                       double Jinv[9]) noexcept {
  for (int i = 0; i < 9; ++i) Jm[i] = Jx[i] - 0.5 * dt * Jv[i];
  if (inverse3(Jm, Jinv) == 0.0) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) L[3 * i + j] = Jv[3 * i] * Jinv[j] + Jv[3 * i + 1] * Jinv[3 + j] + Jv[3 * i + 2] * Jinv[6 + j];
  return true;
}

namespace detail {

// Volume of a trilinear hexahedron is the trilinear form V = sum_ijk D_ijk x_i y_j z_k with
// D_ijk = integral of det[grad_xi N_i; grad_xi N_j; grad_xi N_k] over the reference cube, fully
// antisymmetric. Hence dV/dr_i = sum_{j<k} D_ijk (r_j x r_k). The table is integrated once with
// 2x2x2 Gauss (exact: the integrand has degree <= 2 in each variable) and snapped to multiples of
// 1/96 to remove round-off. Built once; read-only afterwards (thread-safe static init).
struct MeanGradientTable {
  int num_pairs = 0;
  int pair_j[28] = {}, pair_k[28] = {};
  int num_terms[8] = {};
  int term_pair[8][28] = {};
  double term_coef[8][28] = {};

  MeanGradientTable() {
    const double g = 1.0 / std::sqrt(3.0);
    double D[8][8][8] = {};
    for (int gp = 0; gp < 8; ++gp) {
      const double xi = g * kXi[gp], eta = g * kEta[gp], zeta = g * kZeta[gp];
      double dN[8][3];
      for (int k = 0; k < 8; ++k) {
        dN[k][0] = 0.125 * kXi[k] * (1 + kEta[k] * eta) * (1 + kZeta[k] * zeta);
        dN[k][1] = 0.125 * kEta[k] * (1 + kXi[k] * xi) * (1 + kZeta[k] * zeta);
        dN[k][2] = 0.125 * kZeta[k] * (1 + kXi[k] * xi) * (1 + kEta[k] * eta);
      }
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
          for (int k = 0; k < 8; ++k) {
            const double m[9] = {dN[i][0], dN[i][1], dN[i][2], dN[j][0], dN[j][1],
                                 dN[j][2], dN[k][0], dN[k][1], dN[k][2]};
            D[i][j][k] += det3(m);
          }
    }
    int pair_index[8][8];
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k) pair_index[j][k] = -1;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        for (int k = j + 1; k < 8; ++k) {
          const double c = std::round(D[i][j][k] * 96.0) / 96.0;
          if (c == 0.0) continue;
          if (pair_index[j][k] < 0) {
            pair_index[j][k] = num_pairs;
            pair_j[num_pairs] = j;
            pair_k[num_pairs] = k;
            ++num_pairs;
          }
          term_pair[i][num_terms[i]] = pair_index[j][k];
          term_coef[i][num_terms[i]] = c;
          ++num_terms[i];
        }
  }
};

inline const MeanGradientTable& mean_gradient_table() {
  static const MeanGradientTable table;
  return table;
}

}  // namespace detail

inline double hex8_mean_gradient(const NodeVec& x, NodeVec& b) noexcept {
  const detail::MeanGradientTable& t = detail::mean_gradient_table();
  double cx[28], cy[28], cz[28];
  for (int p = 0; p < t.num_pairs; ++p) {
    const int j = t.pair_j[p], k = t.pair_k[p];
    cx[p] = x[1][j] * x[2][k] - x[2][j] * x[1][k];
    cy[p] = x[2][j] * x[0][k] - x[0][j] * x[2][k];
    cz[p] = x[0][j] * x[1][k] - x[1][j] * x[0][k];
  }
  double volume = 0;
  for (int i = 0; i < 8; ++i) {
    double sx = 0, sy = 0, sz = 0;
    for (int m = 0; m < t.num_terms[i]; ++m) {
      const int p = t.term_pair[i][m];
      const double c = t.term_coef[i][m];
      sx += c * cx[p];
      sy += c * cy[p];
      sz += c * cz[p];
    }
    b[0][i] = sx;
    b[1][i] = sy;
    b[2][i] = sz;
    volume += x[0][i] * sx + x[1][i] * sy + x[2][i] * sz;
  }
  volume *= (1.0 / 3.0);
  if (volume > 0.0) {
    const double r = 1.0 / volume;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) b[i][k] *= r;
  }
  return volume;
}

inline double hex8_volume(const NodeVec& x) noexcept {
  NodeVec b;
  return hex8_mean_gradient(x, b);
}

inline double hex8_max_face_area(const NodeVec& x) noexcept {
  static constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  double max_area2 = 0;
  for (const auto& f : kFaces) {
    double d1[3], d2[3];
    for (int i = 0; i < 3; ++i) {
      d1[i] = x[i][f[2]] - x[i][f[0]];
      d2[i] = x[i][f[3]] - x[i][f[1]];
    }
    const double cx = d1[1] * d2[2] - d1[2] * d2[1];
    const double cy = d1[2] * d2[0] - d1[0] * d2[2];
    const double cz = d1[0] * d2[1] - d1[1] * d2[0];
    max_area2 = std::max(max_area2, cx * cx + cy * cy + cz * cz);
  }
  return 0.5 * std::sqrt(max_area2);
}

inline void hex8_corner_jacobians(const NodeVec& x, double detj[8]) noexcept {
  static constexpr int kNbXi[8] = {1, 0, 3, 2, 5, 4, 7, 6};
  static constexpr int kNbEta[8] = {3, 2, 1, 0, 7, 6, 5, 4};
  static constexpr int kNbZeta[8] = {4, 5, 6, 7, 0, 1, 2, 3};
  for (int k = 0; k < 8; ++k) {
    double J[9];
    for (int a = 0; a < 3; ++a) {
      J[3 * a + 0] = 0.5 * kXi[k] * (x[a][k] - x[a][kNbXi[k]]);
      J[3 * a + 1] = 0.5 * kEta[k] * (x[a][k] - x[a][kNbEta[k]]);
      J[3 * a + 2] = 0.5 * kZeta[k] * (x[a][k] - x[a][kNbZeta[k]]);
    }
    detj[k] = det3(J);
  }
}

namespace detail {

// Shape-function derivatives dN_k/dxi_c at the 2x2x2 Gauss points (+-1/sqrt 3, node order).
struct GaussDerivatives {
  double dN[8][3][8];
  GaussDerivatives() {
    const double g = 1.0 / std::sqrt(3.0);
    for (int gp = 0; gp < 8; ++gp) {
      const double xi = g * kXi[gp], eta = g * kEta[gp], zeta = g * kZeta[gp];
      for (int k = 0; k < 8; ++k) {
        dN[gp][0][k] = 0.125 * kXi[k] * (1 + kEta[k] * eta) * (1 + kZeta[k] * zeta);
        dN[gp][1][k] = 0.125 * kEta[k] * (1 + kXi[k] * xi) * (1 + kZeta[k] * zeta);
        dN[gp][2][k] = 0.125 * kZeta[k] * (1 + kXi[k] * xi) * (1 + kEta[k] * eta);
      }
    }
  }
};

inline const GaussDerivatives& gauss_derivatives() {
  static const GaussDerivatives table;
  return table;
}

inline void gauss_jacobian(const NodeVec& u, const double (&dN)[3][8], double J[9]) {
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int k = 0; k < 8; ++k) s += u[a][k] * dN[c][k];
      J[3 * a + c] = s;
    }
}

}  // namespace detail

inline void hex8_gauss_jacobian(const NodeVec& v, int gp, double J[9]) noexcept {
  detail::gauss_jacobian(v, detail::gauss_derivatives().dN[gp], J);
}

inline bool hex8_gauss_gradients(const NodeVec& x, double B[8][3][8], double detj[8], double (*Jout)[9],
                                 double (*Jinv_out)[9]) noexcept {
  const detail::GaussDerivatives& table = detail::gauss_derivatives();
  bool ok = true;
  for (int gp = 0; gp < 8; ++gp) {
    const auto& dN = table.dN[gp];
    double J[9];
    detail::gauss_jacobian(x, dN, J);
    if (Jout)
      for (int i = 0; i < 9; ++i) Jout[gp][i] = J[i];
    double Jinv[9];
    detj[gp] = inverse3(J, Jinv);
    if (!(detj[gp] > 0.0)) {
      ok = false;
      continue;
    }
    if (Jinv_out)
      for (int i = 0; i < 9; ++i) Jinv_out[gp][i] = Jinv[i];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k)
        B[gp][i][k] = Jinv[0 * 3 + i] * dN[0][k] + Jinv[1 * 3 + i] * dN[1][k] + Jinv[2 * 3 + i] * dN[2][k];
  }
  return ok;
}

}  // namespace plyimpact::element
