// Element pass kernels. Conventions: b[i][k] = dN_k/dx_i; L = sum_k v_k (x) b_k (L_ij = dv_i/dx_j);
// internal force on node k is -V sigma b_k; stresses in Voigt xx yy zz xy yz zx.
// Stress update: *MAT_001 is hypoelastic with the Hughes-Winget incremental rotation
// R = (I - W dt/2)^-1 (I + W dt/2), which is exactly orthogonal, so a rigid rotation carries the
// stress along to round-off (a Jaumann rate would only do so to first order in dt); *MAT_002 is
// total Lagrangian, S = C : E and sigma = F S F^T / J, objective and exact for any rotation.
#include "solver/element_update.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/voigt.hpp"
#include "element/hex8.hpp"
#include "material/composite_damage.hpp"
#include "material/plasticity.hpp"
#include "solver/assumed_strain_hourglass.hpp"

namespace plyimpact::solver {

namespace {

using element::hex8_mean_gradient;
using element::inverse3;
using model::MaterialKind;

// R = (I - dt/2 W)^-1 (I + dt/2 W) for a skew W, in closed form: with Omega = dt/2 W and its axial
// vector w, R = I + 2 (Omega + Omega^2) / (1 + |w|^2) (the Cayley transform; no matrix inverse).
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

// Hypoelastic isotropic update with the rotation R and the strain increment D dt.
inline void isotropic_update(const double R[9], const double D[6], double dt, double lambda, double mu, double s[6]) {
  rotate_voigt(R, s, s);
  const double tr = (D[0] + D[1] + D[2]) * dt;
  s[0] += lambda * tr + 2 * mu * D[0] * dt;
  s[1] += lambda * tr + 2 * mu * D[1] * dt;
  s[2] += lambda * tr + 2 * mu * D[2] * dt;
  s[3] += 2 * mu * D[3] * dt;
  s[4] += 2 * mu * D[4] * dt;
  s[5] += 2 * mu * D[5] * dt;
}

// Total-Lagrangian orthotropic stress from the deformation gradient F (row-major) and its
// determinant J: Green-Lagrange strain, S = C_global E, sigma = F S F^T / J.
inline void total_lagrangian_stress(const double F[9], double J, const double* C, double s[6]) {
  double E[6];  // engineering Voigt Green-Lagrange strain
  auto ftf = [&](int i, int j) { return F[i] * F[j] + F[3 + i] * F[3 + j] + F[6 + i] * F[6 + j]; };
  E[0] = 0.5 * (ftf(0, 0) - 1);
  E[1] = 0.5 * (ftf(1, 1) - 1);
  E[2] = 0.5 * (ftf(2, 2) - 1);
  E[3] = ftf(0, 1);
  E[4] = ftf(1, 2);
  E[5] = ftf(2, 0);
  double Sv[6];
  for (int r = 0; r < 6; ++r)
    Sv[r] = C[6 * r] * E[0] + C[6 * r + 1] * E[1] + C[6 * r + 2] * E[2] + C[6 * r + 3] * E[3] + C[6 * r + 4] * E[4] +
            C[6 * r + 5] * E[5];
  const double S[9] = {Sv[0], Sv[3], Sv[5], Sv[3], Sv[1], Sv[4], Sv[5], Sv[4], Sv[2]};
  double T[9];  // F S
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[3 * i + j] = F[3 * i] * S[j] + F[3 * i + 1] * S[3 + j] + F[3 * i + 2] * S[6 + j];
  const double rJ = 1.0 / J;
  auto fsf = [&](int i, int j) { return (T[3 * i] * F[3 * j] + T[3 * i + 1] * F[3 * j + 1] + T[3 * i + 2] * F[3 * j + 2]) * rJ; };
  s[0] = fsf(0, 0);
  s[1] = fsf(1, 1);
  s[2] = fsf(2, 2);
  s[3] = fsf(0, 1);
  s[4] = fsf(1, 2);
  s[5] = fsf(2, 0);
}

// sigma : D with Voigt stress and tensor D (xx yy zz xy yz zx).
inline double stress_power(const double s[6], const double D[6]) {
  return s[0] * D[0] + s[1] * D[1] + s[2] * D[2] + 2 * (s[3] * D[3] + s[4] * D[4] + s[5] * D[5]);
}

// Stable element step (LS-DYNA Theory Manual, time step control for solids) with the bulk
// viscosity term: L / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 L |tr D| in compression, L = V / A_max.
// This is the exact central-difference limit (L/c)(sqrt(1 + xi^2) - xi) of the element's highest
// mode, omega = 2c/L, under the explicit (v^{n+1/2}) viscous damping xi = Q/c that the bulk
// viscosity below gives that mode, provided the viscosity uses the same length L (see there).
inline double element_time_step(double L, double c, double Q) { return L / (Q + std::sqrt(Q * Q + c * c)); }

// Relative decay per cycle of the Q held for the step (step_q).
constexpr double kStepQDecay = 1e-3;

// Q of the step: the bulk-viscosity term of this cycle (0 in expansion), or the element's last held
// Q decayed by kStepQDecay, whichever is larger. Why held: with Q taken afresh the step drops 5.8 %
// (Q2 = 0.06: sqrt(1 + Q2^2) - Q2 = 0.942) whenever the controlling element compresses and comes
// back when it expands, i.e. it oscillates at twice the frequency of the vibration, and a
// central-difference scheme whose step is modulated in phase with a mode is parametrically pumped:
// a one-element thickness mode that controls its own step grew by 1e7 within 1200 cycles at TSSFAC
// 0.85 and 1e10 at 0.88, and lost 45 % of its energy unbooked at 0.9, where the same runs at the
// step held fixed conserve it (tests/core/test_step_modulation.cpp); free blocks and one-element
// cantilevers gained energy at TSSFAC 0.9 this way. Held, Q can fall by only 0.35 % over the
// >= 3.5 cycles of the fastest mode's period at TSSFAC 0.9 (omega dt <= 1.8), so the step's
// modulation is ~0.02 % instead of 5.8 %. Safety is kept: the held Q is never below this cycle's, so
// the step never exceeds the damped-oscillator limit (2/omega)(sqrt(1 + xi^2) - xi); geometry
// (L, c) still acts at once. Cost: after compressing once an element keeps (most of) its Q2 term
// (Q decays by e in 1000 cycles), so a vibrating body runs at the compressing step throughout.
inline double step_q(double L, double c, double trD, double q1, double q2, double q_held) {
  const double Q = trD < 0 ? q2 * c + q1 * L * (-trD) : 0.0;
  const double held = (1 - kStepQDecay) * q_held;
  return Q > held ? Q : held;
}

// Artificial bulk viscosity pressure (compression only), LS-DYNA default form
// q = rho l (Q1 l trD^2 - Q2 c trD), but with the step's characteristic length l = L = V / A_max
// where theory.md 1.4 (after the LS-DYNA TM) has l = V^(1/3); the two agree for a cube. Why: on
// the element's thickness mode (omega = 2c/L) q is an explicit damper of ratio
// xi = (l/L)(Q2 + Q1 l |trD| / c), and the step above is stable only for l = L. With l = V^(1/3) a
// flat element (aspect A, l/L = A^(2/3)) is damped far harder than the step allows: the Hertz
// block's 10.8 x 10.8 x 0.083 mm corner elements had l/L = 25.6, xi = 1.54, a limit of 0.30 L/c,
// and blew up at TSSFAC 0.8-0.9 (tests/core/test_bulk_viscosity_step.cpp).
inline double bulk_viscosity(double rho, double L, double c, double trD, double q1, double q2) {
  if (trD >= 0) return 0.0;
  return rho * L * (q1 * L * trD * trD - q2 * c * trD);
}

inline void gather(const double* a, const Index* conn, double out[3][8]) {
  for (int k = 0; k < 8; ++k) {
    const double* p = a + 3 * std::size_t(conn[k]);
    out[0][k] = p[0];
    out[1][k] = p[1];
    out[2][k] = p[2];
  }
}

inline void scatter(double* f, const Index* conn, const double fe[3][8]) {
  for (int k = 0; k < 8; ++k) {
    double* p = f + 3 * std::size_t(conn[k]);
    p[0] += fe[0][k];
    p[1] += fe[1][k];
    p[2] += fe[2][k];
  }
}

inline void velocity_gradient(const double v[3][8], const double b[3][8], double L[9]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 8; ++k) s += v[i][k] * b[j][k];
      L[3 * i + j] = s;
    }
}

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

inline void record_bad(ChunkResult& r, Index id, double volume, bool nan) {
  if (r.bad_element < 0 || id < r.bad_element) {
    r.bad_element = id;
    r.bad_volume = volume;
    r.bad_is_nan = nan;
  }
}

inline void record_dt(ChunkResult& r, Index id, double dte) {
  if (dte < r.dt_min || (dte == r.dt_min && id < r.dt_element)) {
    r.dt_min = dte;
    r.dt_element = id;
  }
}

// *MAT_054 at one point whose stress is kept in global axes: rotate it into the old material axes
// Qo (rows a, b, c), the strain increment D dt into the new ones Qn = Qo R^T, update in material
// axes (engineering shear), rotate back with Qn. Used by the ELFORM 1 lanes and the ELFORM 2 points.
material::CompositeDamageResult composite_point_update(const material::CompositeDamageParams& p, const double Qo[9],
                                                       const double Qn[9], const double D[6], double dt,
                                                       const material::CompositeDamageContext& ctx, double s[6],
                                                       double* history) {
  double sm[6], de[6], dm[6];
  for (int i = 0; i < 6; ++i) de[i] = D[i] * dt;
  rotate_voigt(Qo, s, sm);  // stress in the old material axes
  rotate_voigt(Qn, de, dm);  // strain increment in the new ones
  for (int i = 3; i < 6; ++i) dm[i] *= 2;  // engineering shear
  const auto res = material::composite_damage_update(p, dm, sm, history, ctx);
  const double Sm[9] = {sm[0], sm[3], sm[5], sm[3], sm[1], sm[4], sm[5], sm[4], sm[2]};
  constexpr int kV[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      double sum = 0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sum += Qn[3 * a + i] * Sm[3 * a + b] * Qn[3 * b + j];
      s[kV[i][j]] = sum;
    }
  return res;
}

// ELFORM 1: one-point integration with Flanagan-Belytschko hourglass control (IHQ 1-5) or the
// Belytschko-Bindeman assumed-strain stabilisation (IHQ 6). Elements are
// processed kLanes at a time: every local quantity is an array over the lanes and every statement a
// loop over them, which the compiler turns into SIMD instructions (8 doubles per AVX-512 register).
// The arithmetic per element is exactly that of a one-element-at-a-time loop; a partial last group
// repeats its last element in the spare lanes and discards them.
constexpr int kLanes = 8;
#define PLYIMPACT_LANES _Pragma("omp simd") for (int l = 0; l < kLanes; ++l)

// Twice the area of the hex8 face (n0 n1 n2 n3) of lane l, squared: |(x2 - x0) x (x3 - x1)|^2.
// A function, not a lambda: GCC does not vectorise `omp simd` loops that hold closures.
inline double face_area2x2(const double (&xe)[3][8][kLanes], int l, int n0, int n1, int n2, int n3) {
  const double d1x = xe[0][n2][l] - xe[0][n0][l], d1y = xe[1][n2][l] - xe[1][n0][l], d1z = xe[2][n2][l] - xe[2][n0][l];
  const double d2x = xe[0][n3][l] - xe[0][n1][l], d2y = xe[1][n3][l] - xe[1][n1][l], d2z = xe[2][n3][l] - xe[2][n1][l];
  const double cx = d1y * d2z - d1z * d2y, cy = d1z * d2x - d1x * d2z, cz = d1x * d2y - d1y * d2x;
  return cx * cx + cy * cy + cz * cz;
}

// Total-Lagrangian stress of lane l: F = J_x J_X^-1; E = (F^T F - I)/2 (engineering Voigt);
// S = C E; sigma = F S F^T / det F. `stiffness(i)` returns entry i of the 6x6 global stiffness.
template <class Stiffness>
inline void total_lagrangian_lane(const double (&Jx)[9][kLanes], const double (&Ji)[9][kLanes], int l,
                                  Stiffness stiffness, double (&s)[6][kLanes]) {
  double F[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      F[3 * i + j] = Jx[3 * i][l] * Ji[j][l] + Jx[3 * i + 1][l] * Ji[3 + j][l] + Jx[3 * i + 2][l] * Ji[6 + j][l];
  const double J =
      F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
  auto ftf = [&](int i, int j) { return F[i] * F[j] + F[3 + i] * F[3 + j] + F[6 + i] * F[6 + j]; };
  const double E[6] = {0.5 * (ftf(0, 0) - 1), 0.5 * (ftf(1, 1) - 1), 0.5 * (ftf(2, 2) - 1),
                       ftf(0, 1),             ftf(1, 2),             ftf(2, 0)};
  double Sv[6];
  for (int a = 0; a < 6; ++a) {
    double sum = 0;
    for (int c = 0; c < 6; ++c) sum += stiffness(6 * a + c) * E[c];
    Sv[a] = sum;
  }
  const double S[9] = {Sv[0], Sv[3], Sv[5], Sv[3], Sv[1], Sv[4], Sv[5], Sv[4], Sv[2]};
  double T[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[3 * i + j] = F[3 * i] * S[j] + F[3 * i + 1] * S[3 + j] + F[3 * i + 2] * S[6 + j];
  const double rJ = 1.0 / J;
  auto fsf = [&](int i, int j) { return (T[3 * i] * F[3 * j] + T[3 * i + 1] * F[3 * j + 1] + T[3 * i + 2] * F[3 * j + 2]) * rJ; };
  s[0][l] = fsf(0, 0), s[1][l] = fsf(1, 1), s[2][l] = fsf(2, 2);
  s[3][l] = fsf(0, 1), s[4][l] = fsf(1, 2), s[5][l] = fsf(2, 0);
}

template <MaterialKind M, int IHQ>
void elform1(const model::Model& model, const model::ElementBlock& blk, BlockState& st, Index begin, Index end,
             const double* __restrict x, const double* __restrict v, double* __restrict f, double dt, ChunkResult& r) {
  constexpr bool kExact = IHQ == 3 || IHQ == 5;
  constexpr bool kStiffness = IHQ == 4 || IHQ == 5;  // Flanagan-Belytschko stiffness forms
  constexpr bool kAssumedStrain = IHQ == 6;           // Belytschko-Bindeman assumed strain
  constexpr bool kTotalLagrangian = M == MaterialKind::OrthotropicElastic;
  const model::Material& mat = model.materials[blk.material];
  const double rho0 = mat.density, c = mat.wave_speed, rho_c2 = mat.wave_modulus;
  const double lambda = mat.iso.lambda, mu = mat.iso.mu;
  const double qm = blk.qm, q1 = blk.q1, q2 = blk.q2;
  const double erode_tsmin = model.control.erode_tsmin;

  for (Index e0 = begin; e0 < end; e0 += kLanes) {
    const int n = int(std::min<Index>(kLanes, end - e0));
    Index elem[kLanes];
    for (int l = 0; l < kLanes; ++l) elem[l] = e0 + std::min(l, n - 1);

    // Gather the nodal coordinates and velocities lane-wise: one SIMD gather per (node, component)
    // instead of 48 scalar loads and stores per element.
    alignas(64) std::int64_t dof0[8][kLanes];  // 3 x node index of local node k of lane l
    for (int l = 0; l < kLanes; ++l) {
      const Index* conn = &blk.conn[8 * std::size_t(elem[l])];
      for (int k = 0; k < 8; ++k) dof0[k][l] = 3 * std::int64_t(conn[k]);
    }
    alignas(64) double xe[3][8][kLanes], ve[3][8][kLanes];
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i)
        PLYIMPACT_LANES {
          xe[i][k][l] = x[dof0[k][l] + i];
          ve[i][k][l] = v[dof0[k][l] + i];
        }
    // Centre Jacobians of x and v: J[3a+c] = sum_k u_a,k xi_c,k / 8.
    alignas(64) double Jx[9][kLanes], Jv[9][kLanes];
    for (int a = 0; a < 3; ++a) {
      PLYIMPACT_LANES {
        double x0 = 0, x1 = 0, x2 = 0, v0 = 0, v1 = 0, v2 = 0;
        for (int k = 0; k < 8; ++k) {
          x0 += xe[a][k][l] * element::kXi[k];
          x1 += xe[a][k][l] * element::kEta[k];
          x2 += xe[a][k][l] * element::kZeta[k];
          v0 += ve[a][k][l] * element::kXi[k];
          v1 += ve[a][k][l] * element::kEta[k];
          v2 += ve[a][k][l] * element::kZeta[k];
        }
        Jx[3 * a][l] = 0.125 * x0, Jx[3 * a + 1][l] = 0.125 * x1, Jx[3 * a + 2][l] = 0.125 * x2;
        Jv[3 * a][l] = 0.125 * v0, Jv[3 * a + 1][l] = 0.125 * v1, Jv[3 * a + 2][l] = 0.125 * v2;
      }
    }
    // Gradient b and volume: one-point (b_k = J0^-T dN_k/dxi(0), V = 8 det J0) or exact FB.
    alignas(64) double b[3][8][kLanes], V[kLanes];
    if constexpr (kExact) {
      const auto& t = element::detail::mean_gradient_table();
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
    } else {
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
          const double xi = element::kXi[k], eta = element::kEta[k], zeta = element::kZeta[k];
          b[0][k][l] = i00 * xi + i10 * eta + i20 * zeta;
          b[1][k][l] = i01 * xi + i11 * eta + i21 * zeta;
          b[2][k][l] = i02 * xi + i12 * eta + i22 * zeta;
        }
        V[l] = 8.0 * det;
      }
    }
    // Mid-step velocity gradient L = J_v (J_x - dt/2 J_v)^-1, rate of deformation D, spin W.
    // Every lane loop below has straight-line bodies over per-lane scalars (no local arrays, no
    // inner loops with lanes outermost), the shape GCC's `omp simd` vectorises reliably.
    alignas(64) double Mi[9][kLanes], L[9][kLanes], D[6][kLanes], Wax[3][kLanes], trD[kLanes], rho[kLanes], det_mid[kLanes];
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
    bool ok[kLanes];  // a valid element (set outside the lane loops: GCC does not vectorise bool lanes)
    for (int l = 0; l < kLanes; ++l) ok[l] = V[l] > 0 && det_mid[l] != 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        PLYIMPACT_LANES L[3 * i + j][l] =
            Jv[3 * i][l] * Mi[j][l] + Jv[3 * i + 1][l] * Mi[3 + j][l] + Jv[3 * i + 2][l] * Mi[6 + j][l];
    PLYIMPACT_LANES {
      D[0][l] = L[0][l], D[1][l] = L[4][l], D[2][l] = L[8][l];
      D[3][l] = 0.5 * (L[1][l] + L[3][l]);
      D[4][l] = 0.5 * (L[5][l] + L[7][l]);
      D[5][l] = 0.5 * (L[6][l] + L[2][l]);
      // Axial vector of the spin W = (L - L^T)/2: (W_zy, W_xz, W_yx).
      Wax[0][l] = 0.5 * (L[7][l] - L[5][l]);
      Wax[1][l] = 0.5 * (L[2][l] - L[6][l]);
      Wax[2][l] = 0.5 * (L[3][l] - L[1][l]);
      trD[l] = D[0][l] + D[1][l] + D[2][l];
      rho[l] = rho0 * blk.volume0[elem[l]] / V[l];
    }
    // Incremental rotation (Cayley form of Hughes-Winget), for the hypoelastic stress and the
    // stiffness hourglass forces.
    alignas(64) double R[9][kLanes];
    if constexpr (!kTotalLagrangian || kStiffness) {  // every incremental material and IHQ 4/5 (not 6: element frame)
      PLYIMPACT_LANES {
        const double h = 0.5 * dt;
        const double w1 = h * Wax[0][l], w2 = h * Wax[1][l], w3 = h * Wax[2][l];
        const double ww = w1 * w1 + w2 * w2 + w3 * w3, cc = 2.0 / (1.0 + ww);
        R[0][l] = 1 + cc * (w1 * w1 - ww), R[1][l] = cc * (-w3 + w1 * w2), R[2][l] = cc * (w2 + w1 * w3);
        R[3][l] = cc * (w3 + w2 * w1), R[4][l] = 1 + cc * (w2 * w2 - ww), R[5][l] = cc * (-w1 + w2 * w3);
        R[6][l] = cc * (-w2 + w3 * w1), R[7][l] = cc * (w1 + w3 * w2), R[8][l] = 1 + cc * (w3 * w3 - ww);
      }
    }
    // Stable step from the largest face area (faces as in hex8_max_face_area); before the stress
    // update because the damage material's TFAIL compares it with the initial step.
    alignas(64) double dte[kLanes], Le[kLanes];  // Le: characteristic length V / A_max (step, bulk viscosity)
    alignas(64) double Qstep[kLanes];            // Q of the step: held one in, this cycle's out (step_q)
    for (int l = 0; l < kLanes; ++l) Qstep[l] = st.step_q[elem[l]];
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
      Qstep[l] = step_q(Le[l], c, trD[l], q1, q2, Qstep[l]);
      dte[l] = element_time_step(Le[l], c, Qstep[l]);
    }
    // Stress update.
    alignas(64) double s[6][kLanes], s_old[6][kLanes];
    int erode_cause[kLanes] = {};  // > 0: the material failed (ErosionCause)
    alignas(64) double Qnew[9][kLanes];  // MAT_054: rotated material axes
    (void)Qnew;
    for (int l = 0; l < kLanes; ++l)
      for (int i = 0; i < 6; ++i) s_old[i][l] = st.stress[6 * std::size_t(elem[l]) + i];
    if constexpr (kTotalLagrangian) {
      alignas(64) double Ji[9][kLanes];
      for (int l = 0; l < kLanes; ++l) {
        const double* src = &blk.reference_jacobian_inverse[9 * std::size_t(elem[l])];
        for (int i = 0; i < 9; ++i) Ji[i][l] = src[i];
      }
      // A ply has one orientation almost always: then the stiffness is broadcast, not copied per lane.
      const int o0 = blk.orientation[elem[0]];
      bool uniform = true;
      for (int l = 1; l < kLanes; ++l) uniform = uniform && blk.orientation[elem[l]] == o0;
      if (uniform) {
        const double* C0 = model.orientations[o0].c_global.data();
        PLYIMPACT_LANES total_lagrangian_lane(Jx, Ji, l, [&](int i) { return C0[i]; }, s);
      } else {
        alignas(64) double Cv[36][kLanes];
        for (int l = 0; l < kLanes; ++l) {
          const double* Cl = model.orientations[blk.orientation[elem[l]]].c_global.data();
          for (int i = 0; i < 36; ++i) Cv[i][l] = Cl[i];
        }
        PLYIMPACT_LANES total_lagrangian_lane(Jx, Ji, l, [&](int i) { return Cv[i][l]; }, s);
      }
    } else if constexpr (M == MaterialKind::Plastic) {
      // J2 plasticity point by point (radial return with its own rotation of stress and back stress).
      for (int l = 0; l < kLanes; ++l) {
        for (int i = 0; i < 6; ++i) s[i][l] = 0;
        if (l >= n || !ok[l]) continue;
        double Rl[9], Dl[6], sl[6];
        for (int i = 0; i < 9; ++i) Rl[i] = R[i][l];
        for (int i = 0; i < 6; ++i) Dl[i] = D[i][l], sl[i] = s_old[i][l];
        const auto res = material::plasticity_update(mat.plastic, Rl, Dl, dt, sl,
                                                     &st.history[std::size_t(elem[l]) * material::kPlasticityHistory]);
        for (int i = 0; i < 6; ++i) s[i][l] = sl[i];
        if (res.failed) erode_cause[l] = int(ErosionCause::PlasticStrain);
      }
    } else if constexpr (M == MaterialKind::CompositeDamage) {
      // Incremental update in the current material axes Q (rows a, b, c), which rotate with the
      // element: Q_new = Q_old R^T. The stress in material axes is Q_old sigma Q_old^T; the strain
      // increment is rotated into the new axes (engineering shear for the material routine).
      for (int l = 0; l < kLanes; ++l) {
        for (int i = 0; i < 6; ++i) s[i][l] = 0;
        if (l >= n || !ok[l]) continue;
        const Index e = elem[l];
        const double* Qo = &st.axes[9 * std::size_t(e)];
        double Qn[9];
        for (int a = 0; a < 3; ++a)
          for (int j = 0; j < 3; ++j) Qn[3 * a + j] = Qo[3 * a] * R[3 * j][l] + Qo[3 * a + 1] * R[3 * j + 1][l] + Qo[3 * a + 2] * R[3 * j + 2][l];
        double sl[6], Dl[6];
        for (int i = 0; i < 6; ++i) sl[i] = s_old[i][l], Dl[i] = D[i][l];
        material::CompositeDamageContext ctx;
        ctx.element_dt = dt > 0 ? dte[l] : 0.0;
        ctx.initial_dt = st.initial_dt[e];
        const auto res = composite_point_update(mat.composite, Qo, Qn, Dl, dt, ctx, sl,
                                                &st.history[std::size_t(e) * material::kCompositeDamageHistory]);
        for (int i = 0; i < 6; ++i) s[i][l] = sl[i];
        for (int i = 0; i < 9; ++i) Qnew[i][l] = Qn[i];
        if (res.erode) erode_cause[l] = int(ErosionCause::CompositeBase) + res.cause;
      }
    } else {
      PLYIMPACT_LANES {
        // sigma* = R sigma R^T, then + lambda tr(D dt) I + 2 mu D dt
        const double S0[9] = {s_old[0][l], s_old[3][l], s_old[5][l], s_old[3][l], s_old[1][l],
                              s_old[4][l], s_old[5][l], s_old[4][l], s_old[2][l]};
        double T[9];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            T[3 * i + j] = R[3 * i][l] * S0[j] + R[3 * i + 1][l] * S0[3 + j] + R[3 * i + 2][l] * S0[6 + j];
        auto rsr = [&](int i, int j) {
          return T[3 * i] * R[3 * j][l] + T[3 * i + 1] * R[3 * j + 1][l] + T[3 * i + 2] * R[3 * j + 2][l];
        };
        const double tr = trD[l] * dt;
        s[0][l] = rsr(0, 0) + lambda * tr + 2 * mu * D[0][l] * dt;
        s[1][l] = rsr(1, 1) + lambda * tr + 2 * mu * D[1][l] * dt;
        s[2][l] = rsr(2, 2) + lambda * tr + 2 * mu * D[2][l] * dt;
        s[3][l] = rsr(0, 1) + 2 * mu * D[3][l] * dt;
        s[4][l] = rsr(1, 2) + 2 * mu * D[4][l] * dt;
        s[5][l] = rsr(2, 0) + 2 * mu * D[5][l] * dt;
      }
    }
    alignas(64) double dIE[kLanes], q[kLanes], dQ[kLanes];
    PLYIMPACT_LANES {
      double p = 0;
      for (int i = 0; i < 3; ++i) p += 0.5 * (s_old[i][l] + s[i][l]) * D[i][l];
      for (int i = 3; i < 6; ++i) p += (s_old[i][l] + s[i][l]) * D[i][l];
      dIE[l] = V[l] * p * dt;
    }
    // V^(1/3) (hourglass area scale) by Newton iterations from above:
    // 2 x the mean half-edge length |J_xi|, |J_eta|, |J_zeta| bounds it (volume <= product of the
    // edges, arithmetic >= geometric mean), and Newton on y^3 = V converges monotonically from
    // above; 7 iterations reach round-off for aspect ratios up to ~50. Unlike std::cbrt it vectorises.
    alignas(64) double cbrtV[kLanes];
    PLYIMPACT_LANES cbrtV[l] = 0;
    for (int c3 = 0; c3 < 3; ++c3)
      PLYIMPACT_LANES cbrtV[l] +=
          std::sqrt(Jx[c3][l] * Jx[c3][l] + Jx[3 + c3][l] * Jx[3 + c3][l] + Jx[6 + c3][l] * Jx[6 + c3][l]);
    PLYIMPACT_LANES {
      // No guard for a non-positive volume: that lane is discarded (and the run stopped) below.
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
    // Bulk viscosity (compression only; length Le as the step, see bulk_viscosity). Its work uses
    // the trapezoid rule, (q_old + q_new)/2, as the force acts over both half steps around it.
    alignas(64) double q_old[kLanes];
    for (int l = 0; l < kLanes; ++l) q_old[l] = st.bulk_q[elem[l]];
    PLYIMPACT_LANES {
      const double ll = Le[l];
      q[l] = trD[l] < 0 ? rho[l] * ll * (q1 * ll * trD[l] * trD[l] - q2 * c * trD[l]) : 0.0;
      dQ[l] = -0.5 * (q_old[l] + q[l]) * trD[l] * V[l] * dt;
    }

    // Internal force -V (sigma - q I) b_k.
    alignas(64) double fe[3][8][kLanes];
    PLYIMPACT_LANES {
      const double sxx = s[0][l] - q[l], syy = s[1][l] - q[l], szz = s[2][l] - q[l];
      const double sxy = s[3][l], syz = s[4][l], szx = s[5][l], mv = -V[l];
      for (int k = 0; k < 8; ++k) {
        fe[0][k][l] = mv * (sxx * b[0][k][l] + sxy * b[1][k][l] + szx * b[2][k][l]);
        fe[1][k][l] = mv * (sxy * b[0][k][l] + syy * b[1][k][l] + syz * b[2][k][l]);
        fe[2][k][l] = mv * (szx * b[0][k][l] + syz * b[1][k][l] + szz * b[2][k][l]);
      }
    }
    // Hourglass: gamma = Gamma - (Gamma . x) b (IHQ 2-5) or Gamma (IHQ 1); rates g = v . gamma.
    alignas(64) double gamma[4][8][kLanes], g[3][4][kLanes], Qh[3][4][kLanes], dHG[kLanes];
    for (int a = 0; a < 4; ++a) {
      alignas(64) double h[3][kLanes] = {};
      if constexpr (IHQ != 1) {
        for (int i = 0; i < 3; ++i)
          for (int k = 0; k < 8; ++k) PLYIMPACT_LANES h[i][l] += element::kGamma[a][k] * xe[i][k][l];
      }
      for (int k = 0; k < 8; ++k)
        PLYIMPACT_LANES gamma[a][k][l] =
            element::kGamma[a][k] - (h[0][l] * b[0][k][l] + h[1][l] * b[1][k][l] + h[2][l] * b[2][k][l]);
      for (int i = 0; i < 3; ++i) {
        PLYIMPACT_LANES g[i][a][l] = 0;
        for (int k = 0; k < 8; ++k) PLYIMPACT_LANES g[i][a][l] += ve[i][k][l] * gamma[a][k][l];
      }
    }
    alignas(64) double Qs[12][kLanes];  // stored hourglass forces of the previous cycle
    alignas(64) double Qp[3][4][kLanes];  // IHQ 6: new forces in the element frame (stored)
    (void)Qp;
    for (int l = 0; l < kLanes; ++l)
      for (int i = 0; i < 12; ++i) Qs[i][l] = st.hourglass[12 * std::size_t(elem[l]) + i];
    if constexpr (kStiffness) {
      // Generalised hourglass forces accumulated from hourglass strain increments and rotated with
      // the element; stiffness scaled with the element's maximum frequency as in FB81:
      // k = QM rho c^2 V sum(b_ik^2) / 4 (keeps omega_hg dt < 2 for QM up to about 0.2 at TSSFAC 0.9).
      PLYIMPACT_LANES {
        double bb = 0;
        for (int i = 0; i < 3; ++i)
          for (int k = 0; k < 8; ++k) bb += b[i][k][l] * b[i][k][l];
        const double kh = 0.25 * qm * rho_c2 * V[l] * bb;
        double e = 0;
        for (int a = 0; a < 4; ++a) {
          const double q0 = Qs[a][l], q1r = Qs[4 + a][l], q2r = Qs[8 + a][l];
          for (int i = 0; i < 3; ++i) {
            const double rotated = R[3 * i][l] * q0 + R[3 * i + 1][l] * q1r + R[3 * i + 2][l] * q2r;
            const double updated = rotated + kh * g[i][a][l] * dt;
            e += 0.5 * (rotated + updated) * g[i][a][l] * dt;
            Qh[i][a][l] = updated;
          }
        }
        dHG[l] = e;
      }
    } else if constexpr (kAssumedStrain) {
      // IHQ 6, assumed-strain stabilisation after Belytschko & Bindeman (CMAME 105, 1993; also
      // Belytschko, Liu & Moran, Nonlinear Finite Elements, sec. 8.7, and code_aster R3.06.11), in
      // the co-rotational element frame x' y' z' (element_frame: orthonormalised centre-Jacobian
      // columns, half-lengths a b c). Hourglass displacement u_i = sum_alpha q_i,alpha h_alpha with
      // h = (xi eta, eta zeta, zeta xi, xi eta zeta) for alpha = 0..3 (the kGamma rows); with
      // gamma . Gamma = 8 the amplitude rate is q' = g'/8 and the generalised force is Q = P/8,
      // P = dW/dq. Assumed hourglass strains (our derivation of the 3-D field, B&B's principle):
      // every normal strain is kept, e.g. eps_x'x' = (q_x,2 zeta + q_x,0 eta + q_x,3 eta zeta) / a;
      // of the shear strains only the parts linear in the third coordinate are kept,
      //   gamma_x'y' = zeta (q_x,1 / b + q_y,2 / a), gamma_y'z' = xi (q_y,2 / c + q_z,0 / b),
      //   gamma_z'x' = eta (q_z,0 / a + q_x,1 / c)
      // (twist, which a plate really carries); the others, e.g. xi q_x,2 / c in gamma_z'x' of a
      // bent thin element, are the parasitic shear that locks bending and are dropped. All 12
      // modes keep stiffness (the three shear-coupled ones form a positive definite 3x3 block).
      // Integrated over the element (mean of zeta^2: 1/3, of (eta zeta)^2: 1/9) with the per-mode
      // moduli of assumed_strain_hourglass.hpp this gives W = sum QM V/6 [E (q/a)^2 for the
      // linear terms, E/3 (q/a)^2 for xi eta zeta, G (shear)^2], exact pure bending of a
      // rectangular element. Forces are accumulated in the element frame (stored), so a rigid
      // rotation carries them exactly; the global forces are E^T Q'.
      alignas(64) double Hm[6][kLanes], Ef[9][kLanes], ha[kLanes], hb[kLanes], hc[kLanes];
      for (int l = 0; l < kLanes; ++l)
        for (int i = 0; i < 6; ++i) Hm[i][l] = st.hourglass_moduli[6 * std::size_t(elem[l]) + i];
      PLYIMPACT_LANES element_frame(Jx, l, Ef, ha, hb, hc);
      alignas(64) double gp[3][4][kLanes];  // g in the element frame
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 4; ++a)
          PLYIMPACT_LANES gp[j][a][l] = Ef[3 * j][l] * g[0][a][l] + Ef[3 * j + 1][l] * g[1][a][l] + Ef[3 * j + 2][l] * g[2][a][l];
      PLYIMPACT_LANES {
        // Amplitude increments d = g' dt / 8; force increments dQ' = dP'/8 = k (...), k = QM V / 24.
        const double d8 = 0.125 * dt, k = qm * V[l] * (1.0 / 24.0);
        const double ia = 1.0 / ha[l], ib = 1.0 / hb[l], ic = 1.0 / hc[l];
        const double kx = k * Hm[0][l] * ia * ia, ky = k * Hm[1][l] * ib * ib, kz = k * Hm[2][l] * ic * ic;
        const double dx1 = gp[0][1][l] * d8, dy2 = gp[1][2][l] * d8, dz0 = gp[2][0][l] * d8;
        const double sxy = dx1 * ib + dy2 * ia, syz = dy2 * ic + dz0 * ib, szx = dz0 * ia + dx1 * ic;
        const double gxy = k * Hm[3][l] * sxy, gyz = k * Hm[4][l] * syz, gzx = k * Hm[5][l] * szx;
        Qp[0][0][l] = Qs[0][l] + kx * gp[0][0][l] * d8;
        Qp[0][1][l] = Qs[1][l] + gxy * ib + gzx * ic;
        Qp[0][2][l] = Qs[2][l] + kx * gp[0][2][l] * d8;
        Qp[0][3][l] = Qs[3][l] + (1.0 / 3.0) * kx * gp[0][3][l] * d8;
        Qp[1][0][l] = Qs[4][l] + ky * gp[1][0][l] * d8;
        Qp[1][1][l] = Qs[5][l] + ky * gp[1][1][l] * d8;
        Qp[1][2][l] = Qs[6][l] + gxy * ia + gyz * ic;
        Qp[1][3][l] = Qs[7][l] + (1.0 / 3.0) * ky * gp[1][3][l] * d8;
        Qp[2][0][l] = Qs[8][l] + gyz * ib + gzx * ia;
        Qp[2][1][l] = Qs[9][l] + kz * gp[2][1][l] * d8;
        Qp[2][2][l] = Qs[10][l] + kz * gp[2][2][l] * d8;
        Qp[2][3][l] = Qs[11][l] + (1.0 / 3.0) * kz * gp[2][3][l] * d8;
        double e = 0;  // trapezoid rule, as IHQ 4/5 (the power Q . g is frame invariant)
        for (int j = 0; j < 3; ++j)
          for (int a = 0; a < 4; ++a) e += 0.5 * (Qs[4 * j + a][l] + Qp[j][a][l]) * gp[j][a][l] * dt;
        dHG[l] = e;
      }
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 4; ++a)
          PLYIMPACT_LANES Qh[i][a][l] = Ef[i][l] * Qp[0][a][l] + Ef[3 + i][l] * Qp[1][a][l] + Ef[6 + i][l] * Qp[2][a][l];
    } else {
      alignas(64) double ah[kLanes];
      PLYIMPACT_LANES ah[l] = 0.25 * qm * rho[l] * cbrtV[l] * cbrtV[l] * c;
      PLYIMPACT_LANES {
        // Work of the viscous forces with the trapezoid rule (previous and new force), like the
        // stress work: the force of a cycle acts over both half steps around it.
        double e = 0;
        for (int i = 0; i < 3; ++i)
          for (int a = 0; a < 4; ++a) {
            Qh[i][a][l] = ah[l] * g[i][a][l];
            e += 0.5 * (Qs[4 * i + a][l] + Qh[i][a][l]) * g[i][a][l] * dt;
          }
        dHG[l] = e;
      }
    }
    PLYIMPACT_LANES {
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 8; ++k)
          fe[i][k][l] -= Qh[i][0][l] * gamma[0][k][l] + Qh[i][1][l] * gamma[1][k][l] +
                         Qh[i][2][l] * gamma[2][k][l] + Qh[i][3][l] * gamma[3][k][l];
    }
    // Per element: checks, stores and the scatter (in element order: deterministic).
    for (int l = 0; l < n; ++l) {
      const Index e = elem[l];
      const double ssum = s[0][l] + s[1][l] + s[2][l] + s[3][l] + s[4][l] + s[5][l];
      if (!ok[l]) {
        record_bad(r, blk.element_id[e], V[l], std::isnan(V[l]));
        continue;
      }
      if (!(dte[l] > 0) || !std::isfinite(ssum)) {
        record_bad(r, blk.element_id[e], V[l], true);
        continue;
      }
      if (dt == 0 && !st.initial_dt.empty()) st.initial_dt[e] = dte[l];
      if (erode_tsmin > 0 && dt > 0 && dte[l] < erode_tsmin) erode_cause[l] = int(ErosionCause::TimeStep);
      if (erode_cause[l] > 0) {
        // Eroded: no stress and no force from now on; the energy it holds stays in the totals and
        // is reported as eroded. Its mass stays on the nodes.
        for (int i = 0; i < 6; ++i) st.stress[6 * std::size_t(e) + i] = 0;
        st.internal_energy[e] += dIE[l];
        st.hourglass_energy[e] += dHG[l];
        r.internal_energy += dIE[l];
        r.hourglass_energy += dHG[l];
        r.eroded.emplace_back(blk.element_id[e], erode_cause[l]);
        r.eroded_energy += st.internal_energy[e] + st.hourglass_energy[e];
        continue;
      }
      if constexpr (M == MaterialKind::CompositeDamage)
        for (int i = 0; i < 9; ++i) st.axes[9 * std::size_t(e) + i] = Qnew[i][l];
      st.volume[e] = V[l];
      for (int i = 0; i < 6; ++i) st.stress[6 * std::size_t(e) + i] = s[i][l];
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 4; ++a)
          st.hourglass[12 * std::size_t(e) + 4 * i + a] = kAssumedStrain ? Qp[i][a][l] : Qh[i][a][l];
      st.bulk_q[e] = q[l];
      st.step_q[e] = Qstep[l];
      st.internal_energy[e] += dIE[l];
      st.hourglass_energy[e] += dHG[l];
      r.internal_energy += dIE[l];
      r.hourglass_energy += dHG[l];
      r.bulk_viscous_energy += dQ[l];
      const Index* conn = &blk.conn[8 * std::size_t(e)];
      for (int k = 0; k < 8; ++k) {
        double* p = f + 3 * std::size_t(conn[k]);
        p[0] += fe[0][k][l];
        p[1] += fe[1][k][l];
        p[2] += fe[2][k][l];
      }
      record_dt(r, blk.element_id[e], dte[l]);
    }
  }
}
#undef PLYIMPACT_LANES

// ELFORM 2: 2x2x2 Gauss points, selectively reduced (B-bar: the volumetric strain rate of every
// point is the element mean; for the total-Lagrangian material the F-bar equivalent
// F_bar = (J_mean / J_gp)^(1/3) F_gp with J_mean = V / V0).
// Materials with history keep it per point (history row 8 e + g). *MAT_003/024 rotate each point's
// stress with that point's spin. *MAT_054 keeps one set of material axes per element, rotated by
// the volume-averaged spin (a ply has one orientation; per-point axes would drift apart only by the
// differences of the point spins, which the B-bar element does not resolve anyway).
// Erosion, our choice: the element is deleted as soon as one of its points fails (like NUMFIP = 1
// on *MAT_ADD_EROSION; the manual's rule for a material's own failure in a fully integrated solid
// could not be confirmed from a source we can cite), exactly as an ELFORM 1 element whose only
// point fails; keeping it would leave a stress-free corner the other points must carry, a
// mechanism the element has no hourglass control for. ERODE/TSMIN applies as in ELFORM 1.
template <MaterialKind M>
void elform2(const model::Model& model, const model::ElementBlock& blk, BlockState& st, Index begin, Index end,
             const double* __restrict x, const double* __restrict v, double* __restrict f, double dt, ChunkResult& r) {
  constexpr bool kTotalLagrangian = M == MaterialKind::OrthotropicElastic;
  constexpr bool kPlastic = M == MaterialKind::Plastic;
  constexpr bool kComposite = M == MaterialKind::CompositeDamage;
  const model::Material& mat = model.materials[blk.material];
  const double rho0 = mat.density, c = mat.wave_speed;
  const double lambda = mat.iso.lambda, mu = mat.iso.mu;
  const double q1 = blk.q1, q2 = blk.q2;
  const double erode_tsmin = model.control.erode_tsmin;
  const std::size_t hsize = std::size_t(mat.history_size());
  const double* X = model.X.data();
  for (Index e = begin; e < end; ++e) {
    const Index* conn = &blk.conn[8 * std::size_t(e)];
    double xe[3][8], ve[3][8], Xe[3][8];
    gather(x, conn, xe);
    gather(v, conn, ve);
    if constexpr (kTotalLagrangian) gather(X, conn, Xe);
    double B[8][3][8], detj[8], Jx[8][9];
    if (!element::hex8_gauss_gradients(xe, B, detj, Jx)) {
      double worst = detj[0];
      for (int g = 1; g < 8; ++g) worst = std::min(worst, detj[g]);
      record_bad(r, blk.element_id[e], worst, std::isnan(worst));
      continue;
    }
    double V = 0, bbar[3][8] = {};
    for (int g = 0; g < 8; ++g) {
      V += detj[g];
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 8; ++k) bbar[i][k] += detj[g] * B[g][i][k];
    }
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) bbar[i][k] /= V;
    st.volume[e] = V;
    const double rho = rho0 * blk.volume0[e] / V;
    const double Jbar = V / blk.volume0[e];
    // Mid-step rates at every point; the mean dilatation rate is their volume average.
    double Lg[8][9];
    double trDbar = 0;
    bool singular = false;
    for (int g = 0; g < 8; ++g) {
      double Jv[9];
      element::hex8_gauss_jacobian(ve, g, Jv);
      singular = singular || !element::mid_step_velocity_gradient(Jx[g], Jv, dt, Lg[g]);
      trDbar += detj[g] * (Lg[g][0] + Lg[g][4] + Lg[g][8]);
    }
    if (singular) {
      record_bad(r, blk.element_id[e], V, false);
      continue;
    }
    trDbar /= V;
    // The element step comes before the material (MAT_054 TFAIL and ERODE/TSMIN need it).
    const double Le = V / element::hex8_max_face_area(xe);  // characteristic length (step, bulk viscosity)
    const double Qstep = step_q(Le, c, trDbar, q1, q2, st.step_q[e]);
    st.step_q[e] = Qstep;
    const double dte = element_time_step(Le, c, Qstep);
    if (dt == 0 && !st.initial_dt.empty()) st.initial_dt[e] = dte;
    double Qo[9] = {}, Qn[9] = {};
    material::CompositeDamageContext ctx;
    if constexpr (kComposite) {
      double Wbar[9] = {};
      for (int g = 0; g < 8; ++g) {
        double D[6], W[9];
        split_rate(Lg[g], D, W);
        for (int i = 0; i < 9; ++i) Wbar[i] += detj[g] * W[i] / V;
      }
      double R[9];
      hughes_winget(Wbar, dt, R);
      std::copy_n(&st.axes[9 * std::size_t(e)], 9, Qo);
      for (int a = 0; a < 3; ++a)
        for (int j = 0; j < 3; ++j) Qn[3 * a + j] = Qo[3 * a] * R[3 * j] + Qo[3 * a + 1] * R[3 * j + 1] + Qo[3 * a + 2] * R[3 * j + 2];
      ctx.element_dt = dt > 0 ? dte : 0.0;
      ctx.initial_dt = st.initial_dt[e];
    }

    double fe[3][8] = {};
    double dIE = 0;
    int erode_cause = 0;  // > 0: a point failed (ErosionCause)
    for (int g = 0; g < 8; ++g) {
      double D[6], W[9];
      split_rate(Lg[g], D, W);
      const double vol_correction = (trDbar - (D[0] + D[1] + D[2])) / 3.0;
      D[0] += vol_correction;
      D[1] += vol_correction;
      D[2] += vol_correction;
      double* s = &st.stress[6 * (8 * std::size_t(e) + g)];
      double* h = kPlastic || kComposite ? &st.history[(8 * std::size_t(e) + g) * hsize] : nullptr;
      const double s_old[6] = {s[0], s[1], s[2], s[3], s[4], s[5]};
      if constexpr (kTotalLagrangian) {
        double Finv[9], F[9];
        velocity_gradient(Xe, B[g], Finv);
        const double Jg = 1.0 / inverse3(Finv, F);
        const double scale = std::cbrt(Jbar / Jg);
        for (double& fij : F) fij *= scale;
        total_lagrangian_stress(F, Jbar, model.orientations[blk.orientation[e]].c_global.data(), s);
      } else if constexpr (kPlastic) {
        double R[9];
        hughes_winget(W, dt, R);
        const auto res = material::plasticity_update(mat.plastic, R, D, dt, s, h);
        if (res.failed && erode_cause == 0) erode_cause = int(ErosionCause::PlasticStrain);
      } else if constexpr (kComposite) {
        const auto res = composite_point_update(mat.composite, Qo, Qn, D, dt, ctx, s, h);
        if (res.erode && erode_cause == 0) erode_cause = int(ErosionCause::CompositeBase) + res.cause;
      } else {
        double R[9];
        hughes_winget(W, dt, R);
        isotropic_update(R, D, dt, lambda, mu, s);
      }
      double s_avg[6];
      for (int i = 0; i < 6; ++i) s_avg[i] = 0.5 * (s_old[i] + s[i]);
      dIE += detj[g] * stress_power(s_avg, D) * dt;
      const double p3 = (s[0] + s[1] + s[2]) / 3.0;
      for (int k = 0; k < 8; ++k) {
        const double bx = B[g][0][k], by = B[g][1][k], bz = B[g][2][k];
        const double cx = p3 * (bbar[0][k] - bx), cy = p3 * (bbar[1][k] - by), cz = p3 * (bbar[2][k] - bz);
        fe[0][k] -= detj[g] * (s[0] * bx + s[3] * by + s[5] * bz + cx);
        fe[1][k] -= detj[g] * (s[3] * bx + s[1] * by + s[4] * bz + cy);
        fe[2][k] -= detj[g] * (s[5] * bx + s[4] * by + s[2] * bz + cz);
      }
    }
    if constexpr (kComposite) std::copy_n(Qn, 9, &st.axes[9 * std::size_t(e)]);
    if (!(dte > 0) || !std::isfinite(dIE)) {
      record_bad(r, blk.element_id[e], V, true);
      continue;
    }
    if (erode_tsmin > 0 && dt > 0 && dte < erode_tsmin) erode_cause = int(ErosionCause::TimeStep);
    st.internal_energy[e] += dIE;
    r.internal_energy += dIE;
    if (erode_cause > 0) {
      // Eroded, as in ELFORM 1: no stress and no force from now on, the energy it holds stays in
      // the totals and is reported as eroded, its mass stays on the nodes.
      std::fill_n(&st.stress[6 * 8 * std::size_t(e)], 6 * 8, 0.0);
      r.eroded.emplace_back(blk.element_id[e], erode_cause);
      r.eroded_energy += st.internal_energy[e] + st.hourglass_energy[e];
      continue;
    }
    const double q = bulk_viscosity(rho, Le, c, trDbar, q1, q2);
    r.bulk_viscous_energy += -0.5 * (st.bulk_q[e] + q) * trDbar * V * dt;  // trapezoid, as in ELFORM 1
    st.bulk_q[e] = q;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) fe[i][k] += q * V * bbar[i][k];
    scatter(f, conn, fe);
    record_dt(r, blk.element_id[e], dte);
  }
}

template <MaterialKind M>
void dispatch_material(const model::Model& model, const model::ElementBlock& blk, BlockState& st, Index begin, Index end,
                       const double* x, const double* v, double* f, double dt, ChunkResult& r) {
  if (blk.elform == 2) return elform2<M>(model, blk, st, begin, end, x, v, f, dt, r);
  switch (blk.ihq) {
    case 1: return elform1<M, 1>(model, blk, st, begin, end, x, v, f, dt, r);
    case 2: return elform1<M, 2>(model, blk, st, begin, end, x, v, f, dt, r);
    case 3: return elform1<M, 3>(model, blk, st, begin, end, x, v, f, dt, r);
    case 4: return elform1<M, 4>(model, blk, st, begin, end, x, v, f, dt, r);
    case 6: return elform1<M, 6>(model, blk, st, begin, end, x, v, f, dt, r);
    default: return elform1<M, 5>(model, blk, st, begin, end, x, v, f, dt, r);
  }
}

}  // namespace

const char* erosion_cause_name(int cause) {
  if (cause == int(ErosionCause::PlasticStrain)) return "plastic_strain";
  if (cause == int(ErosionCause::TimeStep)) return "time_step";
  if (cause > int(ErosionCause::CompositeBase))
    return material::composite_damage_cause_name(
        material::CompositeDamageCause(cause - int(ErosionCause::CompositeBase)));
  return "unknown";
}

void update_elements(const model::Model& model, const model::ElementBlock& block, BlockState& state, Index begin,
                     Index end, const double* x, const double* v, double* f, double dt, ChunkResult& result) {
  // Accumulate in a local copy and write once: results of neighbouring chunks share cache lines and
  // are written by different threads.
  ChunkResult local;
  switch (model.materials[block.material].kind) {
    case MaterialKind::OrthotropicElastic:
      dispatch_material<MaterialKind::OrthotropicElastic>(model, block, state, begin, end, x, v, f, dt, local);
      break;
    case MaterialKind::Plastic:
      dispatch_material<MaterialKind::Plastic>(model, block, state, begin, end, x, v, f, dt, local);
      break;
    case MaterialKind::CompositeDamage:
      dispatch_material<MaterialKind::CompositeDamage>(model, block, state, begin, end, x, v, f, dt, local);
      break;
    default:
      dispatch_material<MaterialKind::IsotropicElastic>(model, block, state, begin, end, x, v, f, dt, local);
  }
  result = local;
}

}  // namespace plyimpact::solver
