// Direct tests of the hex8 geometry kernels (element/hex8.hpp) and their lane versions
// (element/hex8_lanes.hpp), with kLanes different distorted elements in the lanes at once:
//  - against exact values: the one-point gradient and volume of an affine element, the exact
//    volume of a trilinear element with one node moved (1 + h/8), the mid-step velocity gradient
//    of a linear velocity field, V / A_max of a box (its shortest edge);
//  - against exactness properties that hold on any element: sum_k x_k (x) b_k = I for both
//    gradients (linear fields are reproduced), hourglass shape vectors orthogonal to linear fields;
//  - lane kernels against the scalar ones on distorted elements.
// Tolerances: the quantities are O(1) sums of at most ~30 products of O(1) numbers, so round-off
// is a few 1e-16; 1e-13 (absolute or relative as stated) leaves a factor ~100 for the
// distortions' condition and would still catch any wrong coefficient (errors >= 1e-3 here).
#include <gtest/gtest.h>

#include <cmath>

#include "element/hex8.hpp"
#include "element/hex8_gauss_lanes.hpp"
#include "element/hex8_lanes.hpp"
#include "element/kinematics.hpp"

namespace plyimpact {
namespace {

constexpr double kTol = 1e-13;

// A distorted element per lane: the reference cube [-1, 1]^3 scaled, sheared and with every node
// moved by up to 15 % of the edge, different in every lane. Positive corner Jacobians throughout.
void distorted_elements(element::LaneNodeVec& xe) {
  for (int l = 0; l < kLanes; ++l)
    for (int k = 0; k < 8; ++k) {
      const double X[3] = {element::kXi[k], element::kEta[k], element::kZeta[k]};
      for (int i = 0; i < 3; ++i)
        xe[i][k][l] = (1.0 + 0.2 * i + 0.1 * l) * X[i] + 0.1 * X[(i + 1) % 3] +
                      0.15 * std::sin(1.7 * k + 2.3 * i + 0.9 * l) + 0.3 * i;
    }
}

// A linear field u_k = a + G x_k in every lane.
void linear_field(const element::LaneNodeVec& xe, const double G[9], const double a[3], element::LaneNodeVec& u) {
  for (int l = 0; l < kLanes; ++l)
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i)
        u[i][k][l] = a[i] + G[3 * i] * xe[0][k][l] + G[3 * i + 1] * xe[1][k][l] + G[3 * i + 2] * xe[2][k][l];
}

void lane_of(const element::LaneNodeVec& xe, int l, double x[3][8]) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 8; ++k) x[i][k] = xe[i][k][l];
}

constexpr double kG[9] = {0.3, -0.7, 0.2, 0.5, 0.1, -0.4, -0.6, 0.8, 0.25};
constexpr double kA[3] = {1.5, -2.0, 0.7};

TEST(Hex8Kernels, OnePointGradientAndVolumeOfAnAffineElementAreExact) {
  // x = A xi + c: J0 = A, V = 8 det A, b_k = A^-T xi_k / 8 (dN_k/dxi at the centre is xi_k / 8).
  const double A[9] = {2.0, 0.3, -0.1, 0.2, 1.5, 0.4, 0.1, -0.2, 0.8};
  element::LaneNodeVec xe, ve{};
  for (int l = 0; l < kLanes; ++l)
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i)
        xe[i][k][l] = A[3 * i] * element::kXi[k] + A[3 * i + 1] * element::kEta[k] + A[3 * i + 2] * element::kZeta[k] + l;
  alignas(64) double Jx[9][kLanes], Jv[9][kLanes], b[3][8][kLanes], V[kLanes];
  element::hex8_centroid_jacobians_lanes(xe, ve, Jx, Jv);
  element::hex8_centroid_gradient_lanes(Jx, b, V);
  double Ainv[9];
  const double detA = element::inverse3(A, Ainv);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_NEAR(V[l], 8 * detA, kTol * 8 * detA);
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i) {
        const double exact = (Ainv[i] * element::kXi[k] + Ainv[3 + i] * element::kEta[k] + Ainv[6 + i] * element::kZeta[k]) / 8;
        EXPECT_NEAR(b[i][k][l], exact, kTol);
      }
  }
  // The exact (Flanagan-Belytschko) gradient coincides with it on an affine element.
  alignas(64) double bm[3][8][kLanes], Vm[kLanes];
  element::hex8_mean_gradient_lanes(xe, bm, Vm);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_NEAR(Vm[l], 8 * detA, kTol * 8 * detA);
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(bm[i][k][l], b[i][k][l], kTol);
  }
}

TEST(Hex8Kernels, ExactVolumeOfATrilinearElementWithOneNodeMoved) {
  // Unit cube, node 6 (x = y = z = 1) raised by h: the top face becomes z = 1 + h x y (bilinear),
  // so V = integral of (1 + h x y) over the unit square = 1 + h/4 exactly.
  element::LaneNodeVec xe;
  for (int l = 0; l < kLanes; ++l)
    for (int k = 0; k < 8; ++k) {
      xe[0][k][l] = 0.5 * (element::kXi[k] + 1);
      xe[1][k][l] = 0.5 * (element::kEta[k] + 1);
      xe[2][k][l] = 0.5 * (element::kZeta[k] + 1) + (k == 6 ? 0.1 * (l + 1) : 0.0);
    }
  alignas(64) double b[3][8][kLanes], V[kLanes];
  element::hex8_mean_gradient_lanes(xe, b, V);
  for (int l = 0; l < kLanes; ++l) {
    const double exact = 1 + 0.1 * (l + 1) / 4;
    EXPECT_NEAR(V[l], exact, kTol * exact);
    double x[3][8];
    lane_of(xe, l, x);
    EXPECT_NEAR(element::hex8_volume(x), exact, kTol * exact);
  }
}

TEST(Hex8Kernels, GradientsReproduceLinearFieldsOnDistortedElements) {
  // sum_k x_ik b_jk = delta_ij for the one-point gradient (J0 J0^-1) and for the mean gradient
  // (sum_k x_k (x) dV/dx_k = V I for any hexahedron); lane mean gradient = scalar one.
  element::LaneNodeVec xe, ve{};
  distorted_elements(xe);
  alignas(64) double Jx[9][kLanes], Jv[9][kLanes], b1[3][8][kLanes], V1[kLanes], bm[3][8][kLanes], Vm[kLanes];
  element::hex8_centroid_jacobians_lanes(xe, ve, Jx, Jv);
  element::hex8_centroid_gradient_lanes(Jx, b1, V1);
  element::hex8_mean_gradient_lanes(xe, bm, Vm);
  for (int l = 0; l < kLanes; ++l) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s1 = 0, sm = 0;
        for (int k = 0; k < 8; ++k) s1 += xe[i][k][l] * b1[j][k][l], sm += xe[i][k][l] * bm[j][k][l];
        EXPECT_NEAR(s1, i == j ? 1.0 : 0.0, kTol) << "one-point, lane " << l;
        EXPECT_NEAR(sm, i == j ? 1.0 : 0.0, kTol) << "mean, lane " << l;
      }
    double x[3][8], bs[3][8], J[9];
    lane_of(xe, l, x);
    const double Vs = element::hex8_mean_gradient(x, bs);
    EXPECT_NEAR(Vm[l], Vs, kTol * Vs);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) EXPECT_NEAR(bm[i][k][l], bs[i][k], kTol);
    element::hex8_centroid_jacobian(x, J);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(Jx[i][l], J[i], kTol);
    EXPECT_NEAR(V1[l], 8 * element::det3(J), kTol * V1[l]);
    // Distorted: the one-point volume is not the exact one (else this test would not tell them apart).
    EXPECT_GT(std::abs(V1[l] - Vm[l]), 1e-6 * Vm[l]);
  }
}

TEST(Hex8Kernels, MidStepVelocityGradientOfALinearFieldIsExact) {
  // v_k = a + G x_k: J_v = G J_x, so L = G J_x (J_x - dt/2 G J_x)^-1 = G (I - dt/2 G)^-1 exactly.
  element::LaneNodeVec xe, ve;
  distorted_elements(xe);
  linear_field(xe, kG, kA, ve);
  const double dt = 0.3;
  alignas(64) double Jx[9][kLanes], Jv[9][kLanes], L[9][kLanes], det_mid[kLanes];
  element::hex8_centroid_jacobians_lanes(xe, ve, Jx, Jv);
  element::mid_step_velocity_gradient_lanes(Jx, Jv, dt, L, det_mid);
  double M[9], Minv[9], exact[9];
  for (int i = 0; i < 9; ++i) M[i] = (i % 4 == 0 ? 1.0 : 0.0) - 0.5 * dt * kG[i];
  element::inverse3(M, Minv);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      exact[3 * i + j] = kG[3 * i] * Minv[j] + kG[3 * i + 1] * Minv[3 + j] + kG[3 * i + 2] * Minv[6 + j];
  for (int l = 0; l < kLanes; ++l) {
    double Jxl[9], Jvl[9], Ls[9];
    for (int i = 0; i < 9; ++i) Jxl[i] = Jx[i][l], Jvl[i] = Jv[i][l];
    ASSERT_TRUE(element::mid_step_velocity_gradient(Jxl, Jvl, dt, Ls));
    for (int i = 0; i < 9; ++i) {
      EXPECT_NEAR(L[i][l], exact[i], kTol) << "lane " << l << " entry " << i;
      EXPECT_NEAR(L[i][l], Ls[i], kTol);
    }
    EXPECT_NE(det_mid[l], 0.0);
  }
}

TEST(Hex8Kernels, RateSplitAndIncrementalRotationMatchTheScalarKernels) {
  // The lane split and Cayley rotation against element::split_rate and hughes_winget; R orthogonal.
  alignas(64) double L[9][kLanes], D[6][kLanes], Wax[3][kLanes], trD[kLanes], R[9][kLanes];
  for (int i = 0; i < 9; ++i)
    for (int l = 0; l < kLanes; ++l) L[i][l] = kG[i] * (1 + 0.5 * l) + 0.1 * std::cos(i + l);
  element::split_rate_lanes(L, D, Wax, trD);
  const double dt = 0.7;
  element::incremental_rotation_lanes(Wax, dt, R);
  for (int l = 0; l < kLanes; ++l) {
    double Ll[9], Ds[6], Ws[9], Rs[9];
    for (int i = 0; i < 9; ++i) Ll[i] = L[i][l];
    element::split_rate(Ll, Ds, Ws);
    element::hughes_winget(Ws, dt, Rs);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(D[i][l], Ds[i], kTol);
    EXPECT_NEAR(trD[l], Ds[0] + Ds[1] + Ds[2], kTol);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(R[i][l], Rs[i], kTol);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double rrt = 0;
        for (int m = 0; m < 3; ++m) rrt += R[3 * i + m][l] * R[3 * j + m][l];
        EXPECT_NEAR(rrt, i == j ? 1.0 : 0.0, kTol);
      }
  }
}

TEST(Hex8Kernels, HourglassShapeVectorsAreOrthogonalToLinearFields) {
  // Projected gamma (IHQ 2-6) with either gradient: the rates g = v . gamma of a linear velocity
  // field vanish on any element (FB81). The bare Gamma (IHQ 1) only on a parallelepiped, but it is
  // orthogonal to 1, xi, eta, zeta and Gamma_a . Gamma_b = 8 delta_ab.
  element::LaneNodeVec xe, ve, vdummy{};
  distorted_elements(xe);
  linear_field(xe, kG, kA, ve);
  alignas(64) double Jx[9][kLanes], Jv[9][kLanes], b1[3][8][kLanes], bm[3][8][kLanes], V[kLanes];
  element::hex8_centroid_jacobians_lanes(xe, vdummy, Jx, Jv);
  element::hex8_centroid_gradient_lanes(Jx, b1, V);
  element::hex8_mean_gradient_lanes(xe, bm, V);
  alignas(64) double gamma[4][8][kLanes], g[3][4][kLanes];
  for (const auto* b : {&b1, &bm}) {
    element::hex8_hourglass_lanes<true>(xe, ve, *b, gamma, g);
    for (int l = 0; l < kLanes; ++l)
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 4; ++a) EXPECT_NEAR(g[i][a][l], 0.0, kTol) << "lane " << l;
  }
  // A pure hourglass velocity field v = Gamma_0 along x has rate 8 on mode 0 with the one-point
  // gradient (b . Gamma = 0, so gamma . Gamma = Gamma . Gamma).
  for (int l = 0; l < kLanes; ++l)
    for (int k = 0; k < 8; ++k) ve[0][k][l] = element::kGamma[0][k], ve[1][k][l] = ve[2][k][l] = 0;
  element::hex8_hourglass_lanes<true>(xe, ve, b1, gamma, g);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_NEAR(g[0][0][l], 8.0, kTol);
    for (int a = 1; a < 4; ++a) EXPECT_NEAR(g[0][a][l], 0.0, kTol);
  }
  for (int a = 0; a < 4; ++a) {
    double s1 = 0, sx = 0, se = 0, sz = 0;
    for (int k = 0; k < 8; ++k) {
      s1 += element::kGamma[a][k];
      sx += element::kGamma[a][k] * element::kXi[k];
      se += element::kGamma[a][k] * element::kEta[k];
      sz += element::kGamma[a][k] * element::kZeta[k];
    }
    EXPECT_EQ(s1, 0.0);
    EXPECT_EQ(sx, 0.0);
    EXPECT_EQ(se, 0.0);
    EXPECT_EQ(sz, 0.0);
    for (int c = 0; c < 4; ++c) {
      double d = 0;
      for (int k = 0; k < 8; ++k) d += element::kGamma[a][k] * element::kGamma[c][k];
      EXPECT_EQ(d, a == c ? 8.0 : 0.0);
    }
  }
}

TEST(Hex8Kernels, CharacteristicLengthAndCubeRoot) {
  // Box a x b x c (aspect up to 50): V / A_max = the shortest edge. V^(1/3) by the lane Newton
  // iteration against std::cbrt: its 7 steps from the half-edge bound converge quadratically, and
  // at aspect 50 the last step leaves 2.5e-13 (measured; the step before it leaves ~5e-7), so
  // kCbrtTol = 1e-12 separates a converged iteration from one that is a step short.
  // Distorted elements: lane length = scalar V / A_max.
  constexpr double kCbrtTol = 1e-12;
  element::LaneNodeVec xe, ve{};
  for (int l = 0; l < kLanes; ++l) {
    const double e[3] = {1.0 + l, 0.02 * (l + 1), 0.5};  // aspect 1:50 at l = 0
    for (int k = 0; k < 8; ++k) {
      xe[0][k][l] = 0.5 * e[0] * element::kXi[k];
      xe[1][k][l] = 0.5 * e[1] * element::kEta[k];
      xe[2][k][l] = 0.5 * e[2] * element::kZeta[k];
    }
  }
  alignas(64) double Jx[9][kLanes], Jv[9][kLanes], b[3][8][kLanes], V[kLanes], Le[kLanes], cbrtV[kLanes];
  element::hex8_centroid_jacobians_lanes(xe, ve, Jx, Jv);
  element::hex8_centroid_gradient_lanes(Jx, b, V);
  element::hex8_characteristic_length_lanes(xe, V, Le);
  element::hex8_cube_root_volume_lanes(Jx, V, cbrtV);
  for (int l = 0; l < kLanes; ++l) {
    const double shortest = std::min(0.02 * (l + 1), 0.5);
    EXPECT_NEAR(Le[l], shortest, kTol * shortest);
    EXPECT_NEAR(cbrtV[l], std::cbrt(V[l]), kCbrtTol * cbrtV[l]);
  }
  distorted_elements(xe);
  element::hex8_centroid_jacobians_lanes(xe, ve, Jx, Jv);
  element::hex8_mean_gradient_lanes(xe, b, V);
  element::hex8_characteristic_length_lanes(xe, V, Le);
  element::hex8_cube_root_volume_lanes(Jx, V, cbrtV);
  for (int l = 0; l < kLanes; ++l) {
    double x[3][8];
    lane_of(xe, l, x);
    const double Ls = element::hex8_volume(x) / element::hex8_max_face_area(x);
    EXPECT_NEAR(Le[l], Ls, kTol * Ls);
    EXPECT_NEAR(cbrtV[l], std::cbrt(V[l]), kCbrtTol * cbrtV[l]);
  }
}

// The fully integrated pass's sums over the points with the nodes as lanes
// (element/hex8_gauss_lanes.hpp): on a distorted element, sum_g det J_g B_g over all points and over
// a subset equal the scalar kernel's gradients summed point by point (same products, other order:
// round-off only), and with A = det J s Jinv^T the sum is the nodal force sum_g det J s B_g.
TEST(Hex8Kernels, GaussGradientSumsEqualThePointByPointSums) {
  element::LaneNodeVec xl;
  distorted_elements(xl);
  double xe[3][8];
  lane_of(xl, 3, xe);
  double B[8][3][8], detj[8], J[8][9], Jinv[8][9];
  ASSERT_TRUE(element::hex8_gauss_gradients(xe, B, detj, J, Jinv));
  const double s[3][3] = {{1.0, 0.3, -0.2}, {0.3, -0.5, 0.7}, {-0.2, 0.7, 0.4}};
  alignas(64) double A[9][kLanes], T[9][kLanes];
  for (int g = 0; g < 8; ++g)
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) {
        A[3 * i + c][g] = detj[g] * Jinv[g][3 * c + i];
        T[3 * i + c][g] = 0;
        for (int b = 0; b < 3; ++b) T[3 * i + c][g] += detj[g] * s[i][b] * Jinv[g][3 * c + b];
      }
  const int all[8] = {0, 1, 2, 3, 4, 5, 6, 7}, some[3] = {6, 1, 4};
  alignas(64) double sum_all[3][8], sum_some[3][8], forces[3][8];
  element::hex8_gauss_gradient_sum(A, all, 8, sum_all);
  element::hex8_gauss_gradient_sum(A, some, 3, sum_some);
  element::hex8_gauss_gradient_sum(T, all, 8, forces);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 8; ++k) {
      double e_all = 0, e_some = 0, e_force = 0;
      for (int g = 0; g < 8; ++g) {
        e_all += detj[g] * B[g][i][k];
        for (int b = 0; b < 3; ++b) e_force += detj[g] * s[i][b] * B[g][b][k];
      }
      for (int g : some) e_some += detj[g] * B[g][i][k];
      EXPECT_NEAR(sum_all[i][k], e_all, kTol) << i << ' ' << k;
      EXPECT_NEAR(sum_some[i][k], e_some, kTol) << i << ' ' << k;
      EXPECT_NEAR(forces[i][k], e_force, kTol) << i << ' ' << k;
    }
}

}  // namespace
}  // namespace plyimpact
