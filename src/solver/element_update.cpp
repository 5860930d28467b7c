// Element pass kernels. Conventions: b[i][k] = dN_k/dx_i; L = sum_k v_k (x) b_k (L_ij = dv_i/dx_j);
// internal force on node k is -V sigma b_k; stresses in Voigt xx yy zz xy yz zx.
// Stress update: *MAT_001 is hypoelastic with the Hughes-Winget incremental rotation
// R = (I - W dt/2)^-1 (I + W dt/2), which is exactly orthogonal, so a rigid rotation carries the
// stress along to round-off (a Jaumann rate would only do so to first order in dt); *MAT_002 is
// total Lagrangian, S = C : E and sigma = F S F^T / J, objective and exact for any rotation.
#include "solver/element_update.hpp"

#include <cmath>

#include "element/hex8.hpp"

namespace plyimpact::solver {

namespace {

using element::hex8_centroid_gradient;
using element::hex8_mean_gradient;
using element::inverse3;
using model::MaterialKind;

// R = (I - dt/2 W)^-1 (I + dt/2 W) for a skew W (row-major).
inline void hughes_winget(const double W[9], double dt, double R[9]) {
  const double h = 0.5 * dt;
  double A[9], B[9], Ainv[9];
  for (int i = 0; i < 9; ++i) {
    A[i] = -h * W[i];
    B[i] = h * W[i];
  }
  A[0] += 1, A[4] += 1, A[8] += 1;
  B[0] += 1, B[4] += 1, B[8] += 1;
  inverse3(A, Ainv);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[3 * i + j] = Ainv[3 * i] * B[j] + Ainv[3 * i + 1] * B[3 + j] + Ainv[3 * i + 2] * B[6 + j];
}

// sigma <- R sigma R^T
inline void rotate_stress(const double R[9], double s[6]) {
  const double S[9] = {s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2]};
  double T[9];  // R S
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[3 * i + j] = R[3 * i] * S[j] + R[3 * i + 1] * S[3 + j] + R[3 * i + 2] * S[6 + j];
  auto rsr = [&](int i, int j) { return T[3 * i] * R[3 * j] + T[3 * i + 1] * R[3 * j + 1] + T[3 * i + 2] * R[3 * j + 2]; };
  s[0] = rsr(0, 0);
  s[1] = rsr(1, 1);
  s[2] = rsr(2, 2);
  s[3] = rsr(0, 1);
  s[4] = rsr(1, 2);
  s[5] = rsr(2, 0);
}

// Hypoelastic isotropic update with the rotation R and the strain increment D dt.
inline void isotropic_update(const double R[9], const double D[6], double dt, double lambda, double mu, double s[6]) {
  rotate_stress(R, s);
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
// viscosity term: L / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 L |tr D| in compression.
inline double element_time_step(double volume, double max_face_area, double c, double trD, double q1, double q2) {
  const double L = volume / max_face_area;
  const double Q = trD < 0 ? q2 * c + q1 * L * (-trD) : 0.0;
  return L / (Q + std::sqrt(Q * Q + c * c));
}

// Artificial bulk viscosity pressure (compression only), LS-DYNA default form with l = V^(1/3).
inline double bulk_viscosity(double rho, double volume, double c, double trD, double q1, double q2) {
  if (trD >= 0) return 0.0;
  const double l = std::cbrt(volume);
  return rho * l * (q1 * l * trD * trD - q2 * c * trD);
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

// ELFORM 1: one-point integration with Flanagan-Belytschko hourglass control.
template <MaterialKind M, int IHQ>
void elform1(const model::Model& model, const model::ElementBlock& blk, BlockState& st, Index begin, Index end,
             const double* __restrict x, const double* __restrict v, double* __restrict f, double dt, ChunkResult& r) {
  constexpr bool kExact = IHQ == 3 || IHQ == 5;
  constexpr bool kStiffness = IHQ >= 4;
  constexpr bool kTotalLagrangian = M == MaterialKind::OrthotropicElastic;
  const model::Material& mat = model.materials[blk.material];
  const double rho0 = mat.density, c = mat.wave_speed, rho_c2 = mat.wave_modulus;
  const double lambda = mat.iso.lambda, mu = mat.iso.mu;
  const double qm = blk.qm, q1 = blk.q1, q2 = blk.q2;
  const double* X = model.X.data();
  for (Index e = begin; e < end; ++e) {
    const Index* conn = &blk.conn[8 * std::size_t(e)];
    double xe[3][8], ve[3][8], b[3][8];
    gather(x, conn, xe);
    gather(v, conn, ve);
    const double V = kExact ? hex8_mean_gradient(xe, b) : hex8_centroid_gradient(xe, b);
    if (!(V > 0)) {
      record_bad(r, blk.element_id[e], V, std::isnan(V));
      continue;
    }
    st.volume[e] = V;
    const double rho = rho0 * blk.volume0[e] / V;
    double Jx[9], Jv[9], L[9], D[6], W[9];
    element::hex8_centroid_jacobian(xe, Jx);
    element::hex8_centroid_jacobian(ve, Jv);
    if (!element::mid_step_velocity_gradient(Jx, Jv, dt, L)) {
      record_bad(r, blk.element_id[e], V, false);
      continue;
    }
    split_rate(L, D, W);
    const double trD = D[0] + D[1] + D[2];

    double* s = &st.stress[6 * std::size_t(e)];
    const double s_old[6] = {s[0], s[1], s[2], s[3], s[4], s[5]};
    double R[9];
    if constexpr (!kTotalLagrangian || kStiffness) hughes_winget(W, dt, R);
    if constexpr (kTotalLagrangian) {
      double Xe[3][8], Finv[9], F[9];
      gather(X, conn, Xe);
      velocity_gradient(Xe, b, Finv);  // F^-1 = dX/dx = sum_k X_k (x) b_k
      const double det_finv = inverse3(Finv, F);
      total_lagrangian_stress(F, 1.0 / det_finv, model.orientations[blk.orientation[e]].c_global.data(), s);
    } else {
      isotropic_update(R, D, dt, lambda, mu, s);
    }
    double s_avg[6];
    for (int i = 0; i < 6; ++i) s_avg[i] = 0.5 * (s_old[i] + s[i]);
    const double dIE = V * stress_power(s_avg, D) * dt;
    st.internal_energy[e] += dIE;
    r.internal_energy += dIE;

    const double q = bulk_viscosity(rho, V, c, trD, q1, q2);
    const double dQ = -q * trD * V * dt;
    r.bulk_viscous_energy += dQ;

    // Internal force -V (sigma - q I) b_k.
    const double sxx = s[0] - q, syy = s[1] - q, szz = s[2] - q, sxy = s[3], syz = s[4], szx = s[5];
    double fe[3][8];
    for (int k = 0; k < 8; ++k) {
      fe[0][k] = -V * (sxx * b[0][k] + sxy * b[1][k] + szx * b[2][k]);
      fe[1][k] = -V * (sxy * b[0][k] + syy * b[1][k] + syz * b[2][k]);
      fe[2][k] = -V * (szx * b[0][k] + syz * b[1][k] + szz * b[2][k]);
    }

    // Hourglass: rates g_ia = sum_k v_ik gamma_ak, forces -sum_a Q_ia gamma_ak.
    double gamma[4][8];
    if constexpr (IHQ == 1) {
      for (int a = 0; a < 4; ++a)
        for (int k = 0; k < 8; ++k) gamma[a][k] = element::kGamma[a][k];
    } else {
      element::hex8_hourglass_shape(xe, b, gamma);
    }
    double g[3][4];
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 4; ++a) {
        double sum = 0;
        for (int k = 0; k < 8; ++k) sum += ve[i][k] * gamma[a][k];
        g[i][a] = sum;
      }
    double Qh[3][4];
    double dHG = 0;
    if constexpr (kStiffness) {
      // Generalised hourglass forces accumulated from hourglass strain increments and rotated with
      // the element; stiffness scaled with the element's maximum frequency as in FB81:
      // k = QM rho c^2 V sum(b_ik^2) / 4 (keeps omega_hg dt < 2 for QM up to about 0.2 at TSSFAC 0.9).
      double bb = 0;
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 8; ++k) bb += b[i][k] * b[i][k];
      const double kh = 0.25 * qm * rho_c2 * V * bb;
      double* Qs = &st.hourglass[12 * std::size_t(e)];
      for (int a = 0; a < 4; ++a) {
        const double q0 = Qs[a], q1r = Qs[4 + a], q2r = Qs[8 + a];
        for (int i = 0; i < 3; ++i) {
          const double rotated = R[3 * i] * q0 + R[3 * i + 1] * q1r + R[3 * i + 2] * q2r;
          const double updated = rotated + kh * g[i][a] * dt;
          dHG += 0.5 * (rotated + updated) * g[i][a] * dt;
          Qh[i][a] = updated;
        }
      }
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 4; ++a) Qs[4 * i + a] = Qh[i][a];
    } else {
      const double ah = 0.25 * qm * rho * std::cbrt(V * V) * c;
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 4; ++a) {
          Qh[i][a] = ah * g[i][a];
          dHG += Qh[i][a] * g[i][a] * dt;
        }
    }
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k)
        fe[i][k] -= Qh[i][0] * gamma[0][k] + Qh[i][1] * gamma[1][k] + Qh[i][2] * gamma[2][k] + Qh[i][3] * gamma[3][k];
    st.hourglass_energy[e] += dHG;
    r.hourglass_energy += dHG;

    scatter(f, conn, fe);
    const double dte = element_time_step(V, element::hex8_max_face_area(xe), c, trD, q1, q2);
    if (!(dte > 0) || !std::isfinite(s[0] + s[1] + s[2] + s[3] + s[4] + s[5])) {
      record_bad(r, blk.element_id[e], V, true);
      continue;
    }
    record_dt(r, blk.element_id[e], dte);
  }
}

// ELFORM 2: 2x2x2 Gauss points, selectively reduced (B-bar: the volumetric strain rate of every
// point is the element mean; for the total-Lagrangian material the F-bar equivalent
// F_bar = (J_mean / J_gp)^(1/3) F_gp with J_mean = V / V0).
template <MaterialKind M>
void elform2(const model::Model& model, const model::ElementBlock& blk, BlockState& st, Index begin, Index end,
             const double* __restrict x, const double* __restrict v, double* __restrict f, double dt, ChunkResult& r) {
  constexpr bool kTotalLagrangian = M == MaterialKind::OrthotropicElastic;
  const model::Material& mat = model.materials[blk.material];
  const double rho0 = mat.density, c = mat.wave_speed;
  const double lambda = mat.iso.lambda, mu = mat.iso.mu;
  const double q1 = blk.q1, q2 = blk.q2;
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

    double fe[3][8] = {};
    double dIE = 0;
    for (int g = 0; g < 8; ++g) {
      double D[6], W[9];
      split_rate(Lg[g], D, W);
      const double vol_correction = (trDbar - (D[0] + D[1] + D[2])) / 3.0;
      D[0] += vol_correction;
      D[1] += vol_correction;
      D[2] += vol_correction;
      double* s = &st.stress[6 * (8 * std::size_t(e) + g)];
      const double s_old[6] = {s[0], s[1], s[2], s[3], s[4], s[5]};
      if constexpr (kTotalLagrangian) {
        double Finv[9], F[9];
        velocity_gradient(Xe, B[g], Finv);
        const double Jg = 1.0 / inverse3(Finv, F);
        const double scale = std::cbrt(Jbar / Jg);
        for (double& fij : F) fij *= scale;
        total_lagrangian_stress(F, Jbar, model.orientations[blk.orientation[e]].c_global.data(), s);
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
    st.internal_energy[e] += dIE;
    r.internal_energy += dIE;
    const double q = bulk_viscosity(rho, V, c, trDbar, q1, q2);
    r.bulk_viscous_energy += -q * trDbar * V * dt;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) fe[i][k] += q * V * bbar[i][k];
    scatter(f, conn, fe);
    const double dte = element_time_step(V, element::hex8_max_face_area(xe), c, trDbar, q1, q2);
    if (!(dte > 0) || !std::isfinite(dIE)) {
      record_bad(r, blk.element_id[e], V, true);
      continue;
    }
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
    default: return elform1<M, 5>(model, blk, st, begin, end, x, v, f, dt, r);
  }
}

}  // namespace

void update_elements(const model::Model& model, const model::ElementBlock& block, BlockState& state, Index begin,
                     Index end, const double* x, const double* v, double* f, double dt, ChunkResult& result) {
  if (model.materials[block.material].kind == MaterialKind::OrthotropicElastic)
    dispatch_material<MaterialKind::OrthotropicElastic>(model, block, state, begin, end, x, v, f, dt, result);
  else
    dispatch_material<MaterialKind::IsotropicElastic>(model, block, state, begin, end, x, v, f, dt, result);
}

}  // namespace plyimpact::solver
