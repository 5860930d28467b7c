// Assumed natural transverse shear (ANS) of the fully integrated hexahedron, ELFORM -2.
//
// A thin 2x2x2 hexahedron locks in bending: its Gauss points sit off the element's mid-lines, where
// the bilinear interpolation of the transverse displacement does not follow the rotation of the
// normal, and the transverse shear they then see (parasitic shear) stiffens a 10:1 ply by 13-66 %
// (test LaminateBending). The remedy of the solid-shell elements [DB84; HS98]: take the two
// transverse shear components in natural (covariant) form, d_at = (g_a . v,t + g_t . v,a) / 2 with
// t the thin natural direction and a one of the other two, not at the Gauss points but at the
// mid-points of the element's mid-surface edges, where a bending field gives them no parasitic
// part, and interpolate them linearly across the element:
//
//   d_at(point) = (1 - s_b) / 2 d_at(a = 0, b = -1, t = 0) + (1 + s_b) / 2 d_at(a = 0, b = +1, t = 0)
//
// (s_b: the point's natural coordinate b). Every other strain component stays at its Gauss point,
// and the element's B-bar averages the volume rate over each layer of points rather than the whole
// element (solver/element_hex8_selective.cpp).
// Here the difference to the Gauss-point value is returned as rows over the nodal velocities, so
// the element adds it to its rates and the transpose to its forces (power-consistent).
//
// [DB84] E. N. Dvorkin, K.-J. Bathe, A continuum mechanics based four-node shell element for
//        general nonlinear analysis, Engineering Computations 1 (1984) 77-88.
// [HS98] R. Hauptmann, K. Schweizerhof, A systematic development of 'solid-shell' element
//        formulations for linear and non-linear analyses employing only displacement degrees of
//        freedom, Int. J. Numer. Meth. Engng 42 (1998) 49-69.
#pragma once

#include <cmath>

#include "core/lanes.hpp"
#include "element/hex8.hpp"

namespace plyimpact::element {

// The B-bar layer (0 or 1) of Gauss point gp (order of hex8_gauss_gradients): the sign of its
// natural coordinate in the thin direction t, i.e. its side of the mid-surface.
inline int ans_layer(int gp, int t) noexcept {
  const double* s[3] = {kXi, kEta, kZeta};
  return s[t][gp] > 0 ? 1 : 0;
}

// rows[g][m][c][k]: at Gauss point g (order of hex8_gauss_gradients), the change of the covariant
// transverse shear rate m (0: d_at, 1: d_bt, with a = (t + 1) % 3, b = (t + 2) % 3) per unit
// velocity component c of node k: delta d_m(g) = sum_ck rows[g][m][c][k] v[c][k].
using AnsRows = double[8][2][3][8];

namespace detail {

// dN_k / dxi_c at the natural point p.
inline void natural_derivatives(const double (&p)[3], double (&dN)[3][8]) noexcept {
  const double* s[3] = {kXi, kEta, kZeta};
  for (int k = 0; k < 8; ++k) {
    const double f[3] = {1 + s[0][k] * p[0], 1 + s[1][k] * p[1], 1 + s[2][k] * p[2]};
    dN[0][k] = 0.125 * s[0][k] * f[1] * f[2];
    dN[1][k] = 0.125 * s[1][k] * f[0] * f[2];
    dN[2][k] = 0.125 * s[2][k] * f[0] * f[1];
  }
}

// Rows of the covariant rate d_it = (g_i . v,t + g_t . v,i) / 2 at the natural point p.
inline void covariant_shear_rows(const NodeVec& x, const double (&p)[3], int i, int t, double (&r)[3][8]) noexcept {
  double dN[3][8];
  natural_derivatives(p, dN);
  double gi[3] = {}, gt[3] = {};
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 8; ++k) gi[c] += x[c][k] * dN[i][k], gt[c] += x[c][k] * dN[t][k];
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 8; ++k) r[c][k] = 0.5 * (gi[c] * dN[t][k] + gt[c] * dN[i][k]);
}

}  // namespace detail

// The ANS corrections of the element with nodes x and thin natural direction t (0, 1 or 2).
inline void hex8_ans_shear_rows(const NodeVec& x, int t, AnsRows& rows) noexcept {
  const int ab[2] = {(t + 1) % 3, (t + 2) % 3};
  // Tying points: for d_at, the mid-points of the two mid-surface edges along a (a = 0, b = -+1).
  double tied[2][2][3][8];  // [m][side][c][k]
  for (int m = 0; m < 2; ++m) {
    const int i = ab[m], other = ab[1 - m];
    for (int side = 0; side < 2; ++side) {
      double p[3] = {0, 0, 0};
      p[other] = side == 0 ? -1.0 : 1.0;
      detail::covariant_shear_rows(x, p, i, t, tied[m][side]);
    }
  }
  const double g = 1.0 / std::sqrt(3.0);
  for (int gp = 0; gp < 8; ++gp) {
    const double p[3] = {g * kXi[gp], g * kEta[gp], g * kZeta[gp]};
    for (int m = 0; m < 2; ++m) {
      const double s = p[ab[1 - m]];
      const double w0 = 0.5 * (1 - s), w1 = 0.5 * (1 + s);
      double own[3][8];
      detail::covariant_shear_rows(x, p, ab[m], t, own);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 8; ++k) rows[gp][m][c][k] = w0 * tied[m][0][c][k] + w1 * tied[m][1][c][k] - own[c][k];
    }
  }
}

// The same tying for a total-Lagrangian material, on the Green-Lagrange strain: its covariant
// components E_it = (g_i . g_t - G_i . G_t) / 2 (current base vectors g from x, reference G from X)
// have the covariant rates d_it above, so tying them keeps the material's stress consistent with
// the forces. dE[g][m]: the change at Gauss point g, m as in AnsRows.
inline void hex8_ans_green_lagrange(const NodeVec& x, const NodeVec& X, int t, double (&dE)[8][2]) noexcept {
  const int ab[2] = {(t + 1) % 3, (t + 2) % 3};
  const auto covariant = [&](const double (&p)[3], int i) {
    double dN[3][8];
    detail::natural_derivatives(p, dN);
    double e = 0;
    for (int c = 0; c < 3; ++c) {
      double gi = 0, gt = 0, Gi = 0, Gt = 0;
      for (int k = 0; k < 8; ++k) {
        gi += x[c][k] * dN[i][k], gt += x[c][k] * dN[t][k];
        Gi += X[c][k] * dN[i][k], Gt += X[c][k] * dN[t][k];
      }
      e += 0.5 * (gi * gt - Gi * Gt);
    }
    return e;
  };
  double tied[2][2];
  for (int m = 0; m < 2; ++m)
    for (int side = 0; side < 2; ++side) {
      double p[3] = {0, 0, 0};
      p[ab[1 - m]] = side == 0 ? -1.0 : 1.0;
      tied[m][side] = covariant(p, ab[m]);
    }
  const double g = 1.0 / std::sqrt(3.0);
  for (int gp = 0; gp < 8; ++gp) {
    const double p[3] = {g * kXi[gp], g * kEta[gp], g * kZeta[gp]};
    for (int m = 0; m < 2; ++m) {
      const double s = p[ab[1 - m]];
      dE[gp][m] = 0.5 * (1 - s) * tied[m][0] + 0.5 * (1 + s) * tied[m][1] - covariant(p, ab[m]);
    }
  }
}

// Cartesian rate of deformation (Voigt xx yy zz xy yz zx, tensor shear) of the covariant changes
// dd[m] at a point whose inverse Jacobian is Jinv (row c: the contravariant base vector G^c):
// dD = sum_m dd[m] (G^i G^t + G^t G^i), i = (t + 1 + m) % 3 (D = sum_ab d_ab G^a G^b).
inline void ans_cartesian_rate(const double Jinv[9], int t, const double (&dd)[2], double dD[6]) noexcept {
  const double* Gt = &Jinv[3 * t];
  for (int q = 0; q < 6; ++q) dD[q] = 0;
  static constexpr int kP[6] = {0, 1, 2, 0, 1, 2}, kQ[6] = {0, 1, 2, 1, 2, 0};
  for (int m = 0; m < 2; ++m) {
    const double* Gi = &Jinv[3 * ((t + 1 + m) % 3)];
    for (int q = 0; q < 6; ++q) dD[q] += dd[m] * (Gi[kP[q]] * Gt[kQ[q]] + Gt[kP[q]] * Gi[kQ[q]]);
  }
}

// The work-conjugate of the covariant changes: S_m = 2 G^i . s . G^t for the stress s (Voigt,
// tensor), so that s : dD = sum_m S_m dd[m]; the force on component c of node k is then
// -det J sum_m S_m rows[g][m][c][k].
inline void ans_conjugate_stress(const double Jinv[9], int t, const double s[6], double (&S)[2]) noexcept {
  const double* Gt = &Jinv[3 * t];
  const double sg[3] = {s[0] * Gt[0] + s[3] * Gt[1] + s[5] * Gt[2], s[3] * Gt[0] + s[1] * Gt[1] + s[4] * Gt[2],
                        s[5] * Gt[0] + s[4] * Gt[1] + s[2] * Gt[2]};
  for (int m = 0; m < 2; ++m) {
    const double* Gi = &Jinv[3 * ((t + 1 + m) % 3)];
    S[m] = 2 * (Gi[0] * sg[0] + Gi[1] * sg[1] + Gi[2] * sg[2]);
  }
}

// The element pass's form of the same tying, per element (the rows above are its matrix form, for
// the stiffness of the stable step; the test AssumedShearElement holds the two to each other):
//  - begin: base vectors and velocity derivatives at the four tying points (end-of-step geometry
//    x; the mid-step one is x - dt/2 v), the tied covariant rates;
//  - rate_change_lanes, at the Gauss points (lanes): the Cartesian change of each one's rate, from
//    its own covariant rates d_it = (g_i . v,t + g_t . v,i) / 2 at the mid-step Jacobian Jm
//    (inverse Jm_inv) and the velocity Jacobian Jv;
//  - stress_for_gradients_lanes: the work conjugate S_m = 2 G^i . s' . G^t of each point's
//    deviatoric stress s' (end geometry), and the stress whose B^T gives the standard forces less
//    the point's own covariant shear, s - sum_m S_m sym(g_i g_t); it books S_m with the points'
//    interpolation weights for the tying points;
//  - add_tied_forces: the booked S_m times the tying points' rows (end geometry).
class AnsElement {
 public:
  void begin(const NodeVec& x, const NodeVec& v, double dt, int t) noexcept {
    t_ = t;
    const Tying& ty = tying(t);
    for (int m = 0; m < 2; ++m)
      for (int side = 0; side < 2; ++side) {
        const Edge& edge = ty.edge[m][side];
        // Sums in locals, stored once: the compiler cannot tell the member g_ from x and v, and
        // would otherwise store and reload every partial sum.
        double gi[3] = {}, gt[3] = {}, vi[3] = {}, vt[3] = {};
        for (int c = 0; c < 3; ++c)
          for (int q = 0; q < 4; ++q) {
            const int k = edge.node[q];
            gi[c] += x[c][k] * edge.di[q], gt[c] += x[c][k] * edge.dt[q];
            vi[c] += v[c][k] * edge.di[q], vt[c] += v[c][k] * edge.dt[q];
          }
        double d = 0;  // at the mid-step geometry
        for (int c = 0; c < 3; ++c) d += (gi[c] - 0.5 * dt * vi[c]) * vt[c] + (gt[c] - 0.5 * dt * vt[c]) * vi[c];
        for (int c = 0; c < 3; ++c) g_[m][side][0][c] = gi[c], g_[m][side][1][c] = gt[c];
        tied_[m][side] = 0.5 * d;
        booked_[m][side] = 0;
      }
  }

  // The Cartesian change dD (tensor Voigt) of every point's rate, lanes = points (hex8_gauss_lanes.hpp).
  void rate_change_lanes(const LaneVec<9>& Jm, const LaneVec<9>& Jv, const LaneVec<9>& Jm_inv,
                         LaneVec<6>& dD) const noexcept {
    const int t = t_;
    for (int q = 0; q < 6; ++q) PLYIMPACT_LANES dD[q][l] = 0;
    for (int m = 0; m < 2; ++m) {
      const int i = (t + 1 + m) % 3;
      const double tied0 = tied_[m][0], tied1 = tied_[m][1];
      const double* w1 = weights(m);
      PLYIMPACT_LANES {
        double own = 0;
        for (int c = 0; c < 3; ++c) own += Jm[3 * c + i][l] * Jv[3 * c + t][l] + Jm[3 * c + t][l] * Jv[3 * c + i][l];
        const double dd = (1 - w1[l]) * tied0 + w1[l] * tied1 - 0.5 * own;
        const double gi0 = Jm_inv[3 * i][l], gi1 = Jm_inv[3 * i + 1][l], gi2 = Jm_inv[3 * i + 2][l];
        const double gt0 = Jm_inv[3 * t][l], gt1 = Jm_inv[3 * t + 1][l], gt2 = Jm_inv[3 * t + 2][l];
        dD[0][l] += dd * 2 * gi0 * gt0;
        dD[1][l] += dd * 2 * gi1 * gt1;
        dD[2][l] += dd * 2 * gi2 * gt2;
        dD[3][l] += dd * (gi0 * gt1 + gt0 * gi1);
        dD[4][l] += dd * (gi1 * gt2 + gt1 * gi2);
        dD[5][l] += dd * (gi2 * gt0 + gt2 * gi0);
      }
    }
  }

  // Every point's stress for its B^T forces, s - sum_m S_m sym(g_i g_t) with S_m = 2 G^i . s' . G^t
  // (s' = s - p3 I; end geometry Jx, Jinv), and the S_m booked for the tying points.
  void stress_for_gradients_lanes(const LaneVec<9>& Jx, const LaneVec<9>& Jinv, const LaneScalar& detj,
                                  const LaneVec<6>& s, const LaneScalar& p3, LaneVec<6>& s_out) noexcept {
    const int t = t_;
    for (int q = 0; q < 6; ++q) PLYIMPACT_LANES s_out[q][l] = s[q][l];
    for (int m = 0; m < 2; ++m) {
      const int i = (t + 1 + m) % 3;
      const double* w1 = weights(m);
      alignas(64) double b0[kLanes], b1[kLanes];
      PLYIMPACT_LANES {
        const double d0 = s[0][l] - p3[l], d1 = s[1][l] - p3[l], d2 = s[2][l] - p3[l];
        const double gt0 = Jinv[3 * t][l], gt1 = Jinv[3 * t + 1][l], gt2 = Jinv[3 * t + 2][l];
        const double sg0 = d0 * gt0 + s[3][l] * gt1 + s[5][l] * gt2;
        const double sg1 = s[3][l] * gt0 + d1 * gt1 + s[4][l] * gt2;
        const double sg2 = s[5][l] * gt0 + s[4][l] * gt1 + d2 * gt2;
        const double S = 2 * (Jinv[3 * i][l] * sg0 + Jinv[3 * i + 1][l] * sg1 + Jinv[3 * i + 2][l] * sg2);
        const double ci0 = Jx[i][l], ci1 = Jx[3 + i][l], ci2 = Jx[6 + i][l];  // g_i: column i of Jx
        const double ct0 = Jx[t][l], ct1 = Jx[3 + t][l], ct2 = Jx[6 + t][l];
        s_out[0][l] -= S * ci0 * ct0;
        s_out[1][l] -= S * ci1 * ct1;
        s_out[2][l] -= S * ci2 * ct2;
        s_out[3][l] -= 0.5 * S * (ci0 * ct1 + ct0 * ci1);
        s_out[4][l] -= 0.5 * S * (ci1 * ct2 + ct1 * ci2);
        s_out[5][l] -= 0.5 * S * (ci2 * ct0 + ct2 * ci0);
        b1[l] = detj[l] * S * w1[l];
        b0[l] = detj[l] * S - b1[l];
      }
      for (int l = 0; l < kLanes; ++l) booked_[m][0] += b0[l], booked_[m][1] += b1[l];
    }
  }

  void add_tied_forces(double (&fe)[3][8]) const noexcept {
    const Tying& ty = tying(t_);
    for (int m = 0; m < 2; ++m)
      for (int side = 0; side < 2; ++side) {
        const Edge& edge = ty.edge[m][side];
        const double gi[3] = {g_[m][side][0][0], g_[m][side][0][1], g_[m][side][0][2]};  // locals: fe may alias
        const double gt[3] = {g_[m][side][1][0], g_[m][side][1][1], g_[m][side][1][2]};
        const double b = 0.5 * booked_[m][side];
        for (int q = 0; q < 4; ++q) {
          const int k = edge.node[q];
          for (int c = 0; c < 3; ++c) fe[c][k] -= b * (gi[c] * edge.dt[q] + gt[c] * edge.di[q]);
        }
      }
  }

 private:
  // A tying point, the mid-point of a mid-surface edge: only the four nodes on that side of the
  // element have nonzero natural derivatives there, dN/dxi_i and dN/dxi_t = +-1/4.
  struct Edge {
    int node[4];
    double di[4], dt[4];
  };
  struct Tying {
    Edge edge[2][2];  // [m][side]
  };
  static const Tying& tying(int t) noexcept {
    static const Tying tables[3] = {make(0), make(1), make(2)};
    return tables[t];
  }
  static Tying make(int t) noexcept {
    Tying ty{};
    for (int m = 0; m < 2; ++m)
      for (int side = 0; side < 2; ++side) {
        const int i = (t + 1 + m) % 3;
        double p[3] = {0, 0, 0};
        p[(t + 2 - m) % 3] = side == 0 ? -1.0 : 1.0;  // the other in-plane direction
        double dN[3][8];
        detail::natural_derivatives(p, dN);
        Edge& edge = ty.edge[m][side];
        int q = 0;
        for (int k = 0; k < 8; ++k)
          if (dN[i][k] != 0 || dN[t][k] != 0) edge.node[q] = k, edge.di[q] = dN[i][k], edge.dt[q] = dN[t][k], ++q;
      }
    return ty;
  }
  // Interpolation weights of the tying point on side 1 at the eight points, (1 + s) / 2 with s the
  // point's natural coordinate along the other in-plane direction, for pair m.
  const double* weights(int m) const noexcept {
    static const Weights table;
    return table.w[t_][m];
  }
  struct Weights {
    alignas(64) double w[3][2][kLanes];
    Weights() {
      const double* s[3] = {kXi, kEta, kZeta};
      for (int t = 0; t < 3; ++t)
        for (int m = 0; m < 2; ++m)
          for (int gp = 0; gp < kLanes; ++gp) w[t][m][gp] = 0.5 * (1 + s[(t + 2 - m) % 3][gp] / std::sqrt(3.0));
    }
  };

  int t_ = 2;
  double g_[2][2][2][3] = {};  // [m][side][g_i, g_t]: tying-point base vectors, end geometry
  double tied_[2][2] = {};     // tied covariant rates, mid-step geometry
  double booked_[2][2] = {};   // sum over the points of det J S_m x weight
};

}  // namespace plyimpact::element
