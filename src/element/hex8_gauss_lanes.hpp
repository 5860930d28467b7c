// The 2x2x2 Gauss points of ONE hexahedron as the kLanes lanes (core/lanes.hpp): the fully
// integrated element pass computes the Jacobians, their inverses and the gradients of its eight
// points as straight-line lane loops, a[component][lane] with lane = point (the point order of
// hex8_gauss_gradients). Same formulas as the scalar kernels of hex8.hpp; test_hex8_kernels.cpp
// holds them to those.
#pragma once

#include <cmath>

#include "core/lanes.hpp"
#include "element/hex8.hpp"

namespace plyimpact::element {

static_assert(kLanes == 8, "one lane per Gauss point of the 2x2x2 rule");

using GaussNodeLanes = double[3][8][kLanes];  // [component][node][point]

// dN_k/dxi_c at the eight points, [c][k][point], and transposed, [c][point][k].
struct GaussLaneTable {
  alignas(64) double dN[3][8][kLanes];
  alignas(64) double dNT[3][kLanes][8];
  GaussLaneTable() {
    const double g = 1.0 / std::sqrt(3.0);
    for (int gp = 0; gp < kLanes; ++gp) {
      const double xi = g * kXi[gp], eta = g * kEta[gp], zeta = g * kZeta[gp];
      for (int k = 0; k < 8; ++k) {
        dN[0][k][gp] = 0.125 * kXi[k] * (1 + kEta[k] * eta) * (1 + kZeta[k] * zeta);
        dN[1][k][gp] = 0.125 * kEta[k] * (1 + kXi[k] * xi) * (1 + kZeta[k] * zeta);
        dN[2][k][gp] = 0.125 * kZeta[k] * (1 + kXi[k] * xi) * (1 + kEta[k] * eta);
        for (int c = 0; c < 3; ++c) dNT[c][gp][k] = dN[c][k][gp];
      }
    }
  }
};

inline const GaussLaneTable& gauss_lane_table() {
  static const GaussLaneTable table;
  return table;
}

// J[3a+c][point] = sum_k u_a,k dN_k/dxi_c at every point (u = x: dx/dxi; u = v: dv/dxi).
// The nine components accumulate side by side, node by node: each still adds its nodes in order
// (the same values), but nine independent multiply-adds are in flight instead of one component's
// chain of eight dependent ones.
PLYIMPACT_LANE_KERNEL void hex8_gauss_jacobians_lanes(const NodeVec& u, LaneVec<9>& J) {
  const auto& dN = gauss_lane_table().dN;
  alignas(64) double acc[9][kLanes] = {};
  for (int k = 0; k < 8; ++k)
    for (int a = 0; a < 3; ++a) {
      const double uk = u[a][k];
      for (int c = 0; c < 3; ++c) PLYIMPACT_LANES acc[3 * a + c][l] += uk * dN[c][k][l];
    }
  for (int i = 0; i < 9; ++i) PLYIMPACT_LANES J[i][l] = acc[i][l];
}

// inverse3 per lane: inv = A^-1 (row-major), det = det A (inv not finite where det = 0).
PLYIMPACT_LANE_KERNEL void inverse3_lanes(const LaneVec<9>& A, LaneVec<9>& inv, LaneScalar& det) {
  PLYIMPACT_LANES {
    const double c0 = A[4][l] * A[8][l] - A[5][l] * A[7][l];
    const double c1 = A[5][l] * A[6][l] - A[3][l] * A[8][l];
    const double c2 = A[3][l] * A[7][l] - A[4][l] * A[6][l];
    const double d = A[0][l] * c0 + A[1][l] * c1 + A[2][l] * c2;
    const double r = 1.0 / d;
    det[l] = d;
    inv[0][l] = c0 * r;
    inv[1][l] = (A[2][l] * A[7][l] - A[1][l] * A[8][l]) * r;
    inv[2][l] = (A[1][l] * A[5][l] - A[2][l] * A[4][l]) * r;
    inv[3][l] = c1 * r;
    inv[4][l] = (A[0][l] * A[8][l] - A[2][l] * A[6][l]) * r;
    inv[5][l] = (A[2][l] * A[3][l] - A[0][l] * A[5][l]) * r;
    inv[6][l] = c2 * r;
    inv[7][l] = (A[1][l] * A[6][l] - A[0][l] * A[7][l]) * r;
    inv[8][l] = (A[0][l] * A[4][l] - A[1][l] * A[3][l]) * r;
  }
}

// Gradients B[i][k][point] = dN_k/dx_i = sum_c Jinv[3c+i] dN_k/dxi_c.
PLYIMPACT_LANE_KERNEL void hex8_gauss_gradients_lanes(const LaneVec<9>& Jinv, GaussNodeLanes& B) {
  const auto& dN = gauss_lane_table().dN;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 8; ++k)
      PLYIMPACT_LANES B[i][k][l] = Jinv[i][l] * dN[0][k][l] + Jinv[3 + i][l] * dN[1][k][l] + Jinv[6 + i][l] * dN[2][k][l];
}

// out[i][k] = sum over the points p of `points` (count of them, in that order) of
// sum_c A[3i+c][p] dN_k/dxi_c(p): with A[3i+c] = w det J Jinv[3c+i] the weighted sum of the points'
// gradients dN_k/dx_i (the B-bar's mean gradient), with A[3i+c] = det J (s Jinv^T)[i][c] the nodal
// forces of the stress s, sum_p det J s B. Lanes are the eight nodes here: a sum over the points is
// then a broadcast and a multiply-add per point, not a reduction across lanes per node.
PLYIMPACT_LANE_KERNEL void hex8_gauss_gradient_sum(const LaneVec<9>& A, const int* points, int count,
                                                   double (&out)[3][8]) {
  static_assert(kLanes == 8, "node lanes");
  const auto& dNT = gauss_lane_table().dNT;
  // A local accumulator, copied out once: out may alias A as far as the compiler knows, which
  // would make it store and reload the sums after every point.
  alignas(64) double acc[3][8] = {};
  for (int q = 0; q < count; ++q) {
    const int p = points[q];
    for (int i = 0; i < 3; ++i) {
      const double a0 = A[3 * i][p], a1 = A[3 * i + 1][p], a2 = A[3 * i + 2][p];
      PLYIMPACT_LANES acc[i][l] += a0 * dNT[0][p][l] + a1 * dNT[1][p][l] + a2 * dNT[2][p][l];
    }
  }
  for (int i = 0; i < 3; ++i) PLYIMPACT_LANES out[i][l] = acc[i][l];
}

// Sum over the lanes (the element's points), in lane order: the same sum for any thread count.
PLYIMPACT_LANE_KERNEL double lane_sum(const LaneScalar& a) {
  double s = 0;
  for (int l = 0; l < kLanes; ++l) s += a[l];
  return s;
}

}  // namespace plyimpact::element
