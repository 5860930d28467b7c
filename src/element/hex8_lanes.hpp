// Lane versions of the hex8 kernels of hex8.hpp for the one-point element pass (core/lanes.hpp):
// the same formulas for kLanes elements at once, a[component][node][lane]. Each kernel is one or a
// few straight-line lane loops, inline so the pass vectorises them in place. Which scalar kernel a
// lane kernel mirrors is named at each; tests/core/test_hex8_kernels.cpp checks them against it.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/lanes.hpp"
#include "core/types.hpp"
#include "element/hex8.hpp"

namespace plyimpact::element {

using LaneNodeVec = double[3][8][kLanes];  // x[i][k][l]: component i of local node k, lane l

// Nodal coordinates and velocities of the elements `elem` (connectivity rows of 8 node indices):
// one SIMD gather per (node, component) instead of 48 scalar loads and stores per element.
PLYIMPACT_LANE_KERNEL void hex8_gather_lanes(const Index* conn, const Index (&elem)[kLanes], const double* __restrict x,
                              const double* __restrict v, LaneNodeVec& xe, LaneNodeVec& ve) {
  // 3 x node index of local node k of lane l, 32-bit: gathers with 32-bit indices were 2-3 % faster
  // over the pass than 64-bit ones (the solver refuses models of more than 2^31 / 3 nodes).
  alignas(64) std::int32_t dof0[8][kLanes];
  for (int l = 0; l < kLanes; ++l) {
    const Index* c = &conn[8 * std::size_t(elem[l])];
    for (int k = 0; k < 8; ++k) dof0[k][l] = 3 * c[k];
  }
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i)
      PLYIMPACT_LANES {
        xe[i][k][l] = x[dof0[k][l] + i];
        ve[i][k][l] = v[dof0[k][l] + i];
      }
}

// hex8_centroid_jacobian of two fields at once (the pass needs those of x and v):
// J[3a+c] = sum_k u_a,k xi_c,k / 8.
PLYIMPACT_LANE_KERNEL void hex8_centroid_jacobians_lanes(const LaneNodeVec& xe, const LaneNodeVec& ve, LaneVec<9>& Jx,
                                          LaneVec<9>& Jv) {
  for (int a = 0; a < 3; ++a) {
    PLYIMPACT_LANES {
      double x0 = 0, x1 = 0, x2 = 0, v0 = 0, v1 = 0, v2 = 0;
      for (int k = 0; k < 8; ++k) {
        x0 += xe[a][k][l] * kXi[k];
        x1 += xe[a][k][l] * kEta[k];
        x2 += xe[a][k][l] * kZeta[k];
        v0 += ve[a][k][l] * kXi[k];
        v1 += ve[a][k][l] * kEta[k];
        v2 += ve[a][k][l] * kZeta[k];
      }
      Jx[3 * a][l] = 0.125 * x0, Jx[3 * a + 1][l] = 0.125 * x1, Jx[3 * a + 2][l] = 0.125 * x2;
      Jv[3 * a][l] = 0.125 * v0, Jv[3 * a + 1][l] = 0.125 * v1, Jv[3 * a + 2][l] = 0.125 * v2;
    }
  }
}

// One-point gradient b_k = J0^-T dN_k/dxi(0) and volume V = 8 det J0 from the centre Jacobian.
// No guard: a lane with det J0 <= 0 gets non-finite b and is discarded by the caller (V <= 0).
PLYIMPACT_LANE_KERNEL void hex8_centroid_gradient_lanes(const LaneVec<9>& Jx, LaneNodeVec& b, LaneScalar& V) {
  PLYIMPACT_LANES {
    const double a0 = Jx[0][l], a1 = Jx[1][l], a2 = Jx[2][l], a3 = Jx[3][l], a4 = Jx[4][l], a5 = Jx[5][l],
                 a6 = Jx[6][l], a7 = Jx[7][l], a8 = Jx[8][l];
    const double c00 = a4 * a8 - a5 * a7, c01 = a5 * a6 - a3 * a8, c02 = a3 * a7 - a4 * a6;
    const double det = a0 * c00 + a1 * c01 + a2 * c02;
    const double rd = 0.125 / det;
    // (J^-1)[c][i] scaled by 1/8; b[i][k] = sum_c Jinv[c][i] xi_c,k / 8
    const double i00 = c00 * rd, i01 = (a2 * a7 - a1 * a8) * rd, i02 = (a1 * a5 - a2 * a4) * rd;
    const double i10 = c01 * rd, i11 = (a0 * a8 - a2 * a6) * rd, i12 = (a2 * a3 - a0 * a5) * rd;
    const double i20 = c02 * rd, i21 = (a1 * a6 - a0 * a7) * rd, i22 = (a0 * a4 - a1 * a3) * rd;
    for (int k = 0; k < 8; ++k) {
      const double xi = kXi[k], eta = kEta[k], zeta = kZeta[k];
      b[0][k][l] = i00 * xi + i10 * eta + i20 * zeta;
      b[1][k][l] = i01 * xi + i11 * eta + i21 * zeta;
      b[2][k][l] = i02 * xi + i12 * eta + i22 * zeta;
    }
    V[l] = 8.0 * det;
  }
}

// hex8_mean_gradient: Flanagan-Belytschko uniform gradient and exact volume. Unlike the scalar
// kernel b is divided by V whatever its sign (the caller discards lanes with V <= 0).
PLYIMPACT_LANE_KERNEL void hex8_mean_gradient_lanes(const LaneNodeVec& xe, LaneNodeVec& b, LaneScalar& V) {
  const auto& t = detail::mean_gradient_table();
  alignas(64) double cx[28][kLanes], cy[28][kLanes], cz[28][kLanes];
  for (int p = 0; p < t.num_pairs; ++p) {
    const int j = t.pair_j[p], k = t.pair_k[p];
    PLYIMPACT_LANES {
      cx[p][l] = xe[1][j][l] * xe[2][k][l] - xe[2][j][l] * xe[1][k][l];
      cy[p][l] = xe[2][j][l] * xe[0][k][l] - xe[0][j][l] * xe[2][k][l];
      cz[p][l] = xe[0][j][l] * xe[1][k][l] - xe[1][j][l] * xe[0][k][l];
    }
  }
  PLYIMPACT_LANES V[l] = 0;
  for (int i = 0; i < 8; ++i) {
    PLYIMPACT_LANES b[0][i][l] = b[1][i][l] = b[2][i][l] = 0;
    for (int m = 0; m < t.num_terms[i]; ++m) {
      const int p = t.term_pair[i][m];
      const double cf = t.term_coef[i][m];
      PLYIMPACT_LANES {
        b[0][i][l] += cf * cx[p][l];
        b[1][i][l] += cf * cy[p][l];
        b[2][i][l] += cf * cz[p][l];
      }
    }
    PLYIMPACT_LANES V[l] += xe[0][i][l] * b[0][i][l] + xe[1][i][l] * b[1][i][l] + xe[2][i][l] * b[2][i][l];
  }
  PLYIMPACT_LANES {
    V[l] *= 1.0 / 3.0;
    const double rv = 1.0 / V[l];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) b[i][k][l] *= rv;
  }
}

// mid_step_velocity_gradient: L = J_v (J_x - dt/2 J_v)^-1. det_mid: determinant of the mid-step
// Jacobian (0: singular, L not finite).
PLYIMPACT_LANE_KERNEL void mid_step_velocity_gradient_lanes(const LaneVec<9>& Jx, const LaneVec<9>& Jv, double dt, LaneVec<9>& L,
                                             LaneScalar& det_mid) {
  alignas(64) double Mi[9][kLanes];
  PLYIMPACT_LANES {
    const double h = 0.5 * dt;
    const double m0 = Jx[0][l] - h * Jv[0][l], m1 = Jx[1][l] - h * Jv[1][l], m2 = Jx[2][l] - h * Jv[2][l];
    const double m3 = Jx[3][l] - h * Jv[3][l], m4 = Jx[4][l] - h * Jv[4][l], m5 = Jx[5][l] - h * Jv[5][l];
    const double m6 = Jx[6][l] - h * Jv[6][l], m7 = Jx[7][l] - h * Jv[7][l], m8 = Jx[8][l] - h * Jv[8][l];
    const double c00 = m4 * m8 - m5 * m7, c01 = m5 * m6 - m3 * m8, c02 = m3 * m7 - m4 * m6;
    const double det = m0 * c00 + m1 * c01 + m2 * c02;
    const double rd = 1.0 / det;
    Mi[0][l] = c00 * rd, Mi[1][l] = (m2 * m7 - m1 * m8) * rd, Mi[2][l] = (m1 * m5 - m2 * m4) * rd;
    Mi[3][l] = c01 * rd, Mi[4][l] = (m0 * m8 - m2 * m6) * rd, Mi[5][l] = (m2 * m3 - m0 * m5) * rd;
    Mi[6][l] = c02 * rd, Mi[7][l] = (m1 * m6 - m0 * m7) * rd, Mi[8][l] = (m0 * m4 - m1 * m3) * rd;
    det_mid[l] = det;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      PLYIMPACT_LANES L[3 * i + j][l] =
          Jv[3 * i][l] * Mi[j][l] + Jv[3 * i + 1][l] * Mi[3 + j][l] + Jv[3 * i + 2][l] * Mi[6 + j][l];
}

// Rate of deformation D (tensor Voigt xx yy zz xy yz zx), the axial vector of the spin
// W = (L - L^T)/2, (W_zy, W_xz, W_yx), and tr D.
PLYIMPACT_LANE_KERNEL void split_rate_lanes(const LaneVec<9>& L, LaneVec<6>& D, LaneVec<3>& Wax, LaneScalar& trD) {
  PLYIMPACT_LANES {
    D[0][l] = L[0][l], D[1][l] = L[4][l], D[2][l] = L[8][l];
    D[3][l] = 0.5 * (L[1][l] + L[3][l]);
    D[4][l] = 0.5 * (L[5][l] + L[7][l]);
    D[5][l] = 0.5 * (L[6][l] + L[2][l]);
    Wax[0][l] = 0.5 * (L[7][l] - L[5][l]);
    Wax[1][l] = 0.5 * (L[2][l] - L[6][l]);
    Wax[2][l] = 0.5 * (L[3][l] - L[1][l]);
    trD[l] = D[0][l] + D[1][l] + D[2][l];
  }
}

// Hughes-Winget incremental rotation R = (I - W dt/2)^-1 (I + W dt/2) in its closed (Cayley) form,
// as hughes_winget (element/kinematics.hpp), from the spin's axial vector.
PLYIMPACT_LANE_KERNEL void incremental_rotation_lanes(const LaneVec<3>& Wax, double dt, LaneVec<9>& R) {
  PLYIMPACT_LANES {
    const double h = 0.5 * dt;
    const double w1 = h * Wax[0][l], w2 = h * Wax[1][l], w3 = h * Wax[2][l];
    const double ww = w1 * w1 + w2 * w2 + w3 * w3, cc = 2.0 / (1.0 + ww);
    R[0][l] = 1 + cc * (w1 * w1 - ww), R[1][l] = cc * (-w3 + w1 * w2), R[2][l] = cc * (w2 + w1 * w3);
    R[3][l] = cc * (w3 + w2 * w1), R[4][l] = 1 + cc * (w2 * w2 - ww), R[5][l] = cc * (-w1 + w2 * w3);
    R[6][l] = cc * (-w2 + w3 * w1), R[7][l] = cc * (w1 + w3 * w2), R[8][l] = 1 + cc * (w3 * w3 - ww);
  }
}

// Twice the area of the face (n0 n1 n2 n3) of lane l, squared: |(x2 - x0) x (x3 - x1)|^2.
// A function, not a lambda: GCC does not vectorise `omp simd` loops that hold closures.
PLYIMPACT_LANE_KERNEL double face_area2x2(const LaneNodeVec& xe, int l, int n0, int n1, int n2, int n3) {
  const double d1x = xe[0][n2][l] - xe[0][n0][l], d1y = xe[1][n2][l] - xe[1][n0][l], d1z = xe[2][n2][l] - xe[2][n0][l];
  const double d2x = xe[0][n3][l] - xe[0][n1][l], d2y = xe[1][n3][l] - xe[1][n1][l], d2z = xe[2][n3][l] - xe[2][n1][l];
  const double cx = d1y * d2z - d1z * d2y, cy = d1z * d2x - d1x * d2z, cz = d1x * d2y - d1y * d2x;
  return cx * cx + cy * cy + cz * cz;
}

// Characteristic length V / A_max with the faces and area of hex8_max_face_area.
PLYIMPACT_LANE_KERNEL void hex8_characteristic_length_lanes(const LaneNodeVec& xe, const LaneScalar& V, LaneScalar& Le) {
  PLYIMPACT_LANES {
    double area2 = face_area2x2(xe, l, 0, 1, 2, 3);
    const double a1 = face_area2x2(xe, l, 4, 5, 6, 7), a2 = face_area2x2(xe, l, 0, 1, 5, 4);
    const double a3 = face_area2x2(xe, l, 1, 2, 6, 5), a4 = face_area2x2(xe, l, 2, 3, 7, 6);
    const double a5 = face_area2x2(xe, l, 3, 0, 4, 7);
    area2 = a1 > area2 ? a1 : area2;
    area2 = a2 > area2 ? a2 : area2;
    area2 = a3 > area2 ? a3 : area2;
    area2 = a4 > area2 ? a4 : area2;
    area2 = a5 > area2 ? a5 : area2;
    Le[l] = V[l] / (0.5 * std::sqrt(area2));
  }
}

// V^(1/3) by Newton iterations from above: 2 x the mean half-edge length |J_xi|, |J_eta|, |J_zeta|
// bounds it (volume <= product of the edges, arithmetic >= geometric mean), and Newton on y^3 = V
// converges monotonically from above; 7 iterations reach round-off for aspect ratios up to ~50.
// Unlike std::cbrt it vectorises. No guard for V <= 0: that lane is discarded by the caller.
PLYIMPACT_LANE_KERNEL void hex8_cube_root_volume_lanes(const LaneVec<9>& Jx, const LaneScalar& V, LaneScalar& cbrtV) {
  PLYIMPACT_LANES cbrtV[l] = 0;
  for (int c3 = 0; c3 < 3; ++c3)
    PLYIMPACT_LANES cbrtV[l] +=
        std::sqrt(Jx[c3][l] * Jx[c3][l] + Jx[3 + c3][l] * Jx[3 + c3][l] + Jx[6 + c3][l] * Jx[6 + c3][l]);
  PLYIMPACT_LANES {
    const double vol = V[l];
    double y = cbrtV[l] * (2.0 / 3.0);
    y = (2.0 * y + vol / (y * y)) * (1.0 / 3.0);
    y = (2.0 * y + vol / (y * y)) * (1.0 / 3.0);
    y = (2.0 * y + vol / (y * y)) * (1.0 / 3.0);
    y = (2.0 * y + vol / (y * y)) * (1.0 / 3.0);
    y = (2.0 * y + vol / (y * y)) * (1.0 / 3.0);
    y = (2.0 * y + vol / (y * y)) * (1.0 / 3.0);
    y = (2.0 * y + vol / (y * y)) * (1.0 / 3.0);
    cbrtV[l] = y;
  }
}

// Hourglass shape vectors gamma_a = Gamma_a - sum_i (Gamma_a . x_i) b_i (FB81; orthogonal to every
// linear field when sum_k x_k (x) b_k = I), or the bare Gamma_a when kProject is false (IHQ 1),
// and the hourglass rates g[i][a] = sum_k v_ik gamma_ak.
template <bool kProject>
PLYIMPACT_LANE_KERNEL void hex8_hourglass_lanes(const LaneNodeVec& xe, const LaneNodeVec& ve, const LaneNodeVec& b,
                                 double (&gamma)[4][8][kLanes], double (&g)[3][4][kLanes]) {
  // One lane loop per mode with the sums in registers (the same operations in the same order as
  // the three sums written out separately: h, then gamma node by node, then g).
  for (int a = 0; a < 4; ++a)
    PLYIMPACT_LANES {
      double h0 = 0, h1 = 0, h2 = 0;
      if constexpr (kProject)
        for (int k = 0; k < 8; ++k) {
          h0 += kGamma[a][k] * xe[0][k][l];
          h1 += kGamma[a][k] * xe[1][k][l];
          h2 += kGamma[a][k] * xe[2][k][l];
        }
      double g0 = 0, g1 = 0, g2 = 0;
      for (int k = 0; k < 8; ++k) {
        const double gak = kGamma[a][k] - (h0 * b[0][k][l] + h1 * b[1][k][l] + h2 * b[2][k][l]);
        gamma[a][k][l] = gak;
        g0 += ve[0][k][l] * gak;
        g1 += ve[1][k][l] * gak;
        g2 += ve[2][k][l] * gak;
      }
      g[0][a][l] = g0, g[1][a][l] = g1, g[2][a][l] = g2;
    }
}

}  // namespace plyimpact::element
