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
// ELFORM -2 adds the assumed natural transverse shear of element/hex8_ans.hpp to every point's rate
// (before the B-bar correction, which thus keeps the element's mean volume rate) and its transpose,
// with the deviatoric stress, to the forces.
#include <algorithm>
#include <cmath>

#include "element/hex8.hpp"
#include "element/hex8_ans.hpp"
#include "element/kinematics.hpp"
#include "solver/element_families.hpp"
#include "solver/element_step.hpp"
#include "solver/erosion.hpp"
#include "solver/material_registry.hpp"

namespace plyimpact::solver {

namespace {

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

// ELFORM -2 with a total-Lagrangian material: the tied changes of the covariant Green-Lagrange
// strain at Gauss point g in reference Cartesian axes, less the part that changes the volume (as
// the rate form's B-bar correction removes the trace of its change: the pull-back of
// tr(dD)/3 I is (dE : C^-1)/3 C, C = F^T F), engineering Voigt.
void tied_green_lagrange(const double (&Xe)[3][8], int g, int thin, const double (&dE_cov)[2], const double F[9],
                         double dE[6]) {
  double JX[9], JXinv[9];
  element::hex8_gauss_jacobian(Xe, g, JX);
  element::inverse3(JX, JXinv);
  double t[6];  // tensor Voigt
  element::ans_cartesian_rate(JXinv, thin, dE_cov, t);
  double C[9], Cinv[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[3 * i + j] = F[i] * F[j] + F[3 + i] * F[3 + j] + F[6 + i] * F[6 + j];
  element::inverse3(C, Cinv);
  const double trace = t[0] * Cinv[0] + t[1] * Cinv[4] + t[2] * Cinv[8] + 2 * (t[3] * Cinv[1] + t[4] * Cinv[5] + t[5] * Cinv[2]);
  const int row[6] = {0, 4, 8, 1, 5, 2};  // Voigt xx yy zz xy yz zx in the row-major C
  for (int q = 0; q < 6; ++q) dE[q] = (t[q] - trace / 3 * C[row[q]]) * (q < 3 ? 1.0 : 2.0);
}

template <bool kAns, class Material>
void selective(Material& material, const model::Model& model, const model::ElementBlock& blk, BlockState& st,
               Index begin, Index end, const double* __restrict x, const double* __restrict v, double* __restrict f,
               double dt, ChunkResult& r) {
  const model::Material& mat = model.materials[blk.material];
  const double rho0 = mat.density, c = mat.wave_speed;
  const double q1 = blk.q1, q2 = blk.q2;
  const double erode_tsmin = model.control.erode_tsmin;
  const std::size_t hsize = std::size_t(mat.history_size());
  const double* X = model.X.data();
  for (Index e = begin; e < end; ++e) {
    const Index* conn = &blk.conn[8 * std::size_t(e)];
    double xe[3][8], ve[3][8], Xe[3][8];
    gather(x, conn, xe);
    gather(v, conn, ve);
    if constexpr (Material::kTotalLagrangian) gather(X, conn, Xe);
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
    // ELFORM -2: the assumed-shear rows at the mid-step geometry (rates) and at the end (forces).
    [[maybe_unused]] const int thin = kAns ? int(blk.thin_axis[e]) : 0;
    [[maybe_unused]] element::AnsRows ans_end;
    [[maybe_unused]] double ans_rate[8][6];
    [[maybe_unused]] double ans_strain[8][2];  // total-Lagrangian materials: the tied Green-Lagrange change
    if constexpr (kAns && Material::kTotalLagrangian) element::hex8_ans_green_lagrange(xe, Xe, thin, ans_strain);
    if constexpr (kAns) {
      double xm[3][8];
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 8; ++k) xm[i][k] = xe[i][k] - 0.5 * dt * ve[i][k];
      element::AnsRows ans_mid;
      element::hex8_ans_shear_rows(xm, thin, ans_mid);
      element::hex8_ans_shear_rows(xe, thin, ans_end);
      for (int g = 0; g < 8; ++g) {
        double dd[2] = {};
        for (int m = 0; m < 2; ++m)
          for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 8; ++k) dd[m] += ans_mid[g][m][c][k] * ve[c][k];
        double Jv[9], Jm[9], Jm_inv[9];
        element::hex8_gauss_jacobian(ve, g, Jv);
        for (int i = 0; i < 9; ++i) Jm[i] = Jx[g][i] - 0.5 * dt * Jv[i];
        element::inverse3(Jm, Jm_inv);  // singular: caught below by mid_step_velocity_gradient
        element::ans_cartesian_rate(Jm_inv, thin, dd, ans_rate[g]);
      }
    }
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
    // Wave speed of the element's fastest mode (directional_step.hpp): the step's and the bulk
    // viscosity's, as in ELFORM 1.
    const double c_step = st.step_wave_speed.empty() ? c : st.step_wave_speed[e];
    const double Qstep = step_q(Le, c_step, trDbar, q1, q2, st.step_q[e]);
    st.step_q[e] = Qstep;
    const double dte = element_time_step(Le, c_step, Qstep) * (blk.step_scale.empty() ? 1.0 : blk.step_scale[e]);
    if (dt == 0 && !st.initial_dt.empty()) st.initial_dt[e] = dte;
    if constexpr (Material::kElementRotation) {
      double Wbar[9] = {};
      for (int g = 0; g < 8; ++g) {
        double D[6], W[9];
        element::split_rate(Lg[g], D, W);
        for (int i = 0; i < 9; ++i) Wbar[i] += detj[g] * W[i] / V;
      }
      double R[9];
      element::hughes_winget(Wbar, dt, R);
      material.begin_element(e, R, dt, dte);
    }

    double fe[3][8] = {};
    double dIE = 0, dIE_old = 0;  // dIE_old: the previous stress's half, all an eroding element books
    int erode_cause = 0;  // > 0: a point failed (ErosionCause of the first)
    for (int g = 0; g < 8; ++g) {
      double D[6], W[9];
      element::split_rate(Lg[g], D, W);
      if constexpr (kAns)
        for (int i = 0; i < 6; ++i) D[i] += ans_rate[g][i];
      const double vol_correction = (trDbar - (D[0] + D[1] + D[2])) / 3.0;
      D[0] += vol_correction;
      D[1] += vol_correction;
      D[2] += vol_correction;
      double* s = &st.stress[6 * (8 * std::size_t(e) + g)];
      double* h = hsize > 0 ? &st.history[(8 * std::size_t(e) + g) * hsize] : nullptr;
      const double s_old[6] = {s[0], s[1], s[2], s[3], s[4], s[5]};
      material::Point point{e, g, dt, D, W};
      point.element_dt = dte;
      double F[9];
      [[maybe_unused]] double dE[6];  // ELFORM -2, total Lagrangian: read by the material below
      if constexpr (Material::kTotalLagrangian) {
        double Finv[9];
        element::velocity_gradient(Xe, B[g], Finv);
        const double Jg = 1.0 / element::inverse3(Finv, F);
        const double scale = std::cbrt(Jbar / Jg);
        for (double& fij : F) fij *= scale;
        point.F = F;
        point.J = Jbar;
        if constexpr (kAns) {
          tied_green_lagrange(Xe, g, thin, ans_strain[g], F, dE);
          point.dE = dE;
        }
      }
      const int cause = material.update_point(point, s, h);
      if (cause > 0 && erode_cause == 0) erode_cause = cause;
      double s_avg[6];
      for (int i = 0; i < 6; ++i) s_avg[i] = 0.5 * (s_old[i] + s[i]);
      dIE += detj[g] * element::stress_power(s_avg, D) * dt;
      dIE_old += 0.5 * detj[g] * element::stress_power(s_old, D) * dt;
      const double p3 = (s[0] + s[1] + s[2]) / 3.0;
      for (int k = 0; k < 8; ++k) {
        const double bx = B[g][0][k], by = B[g][1][k], bz = B[g][2][k];
        const double cx = p3 * (bbar[0][k] - bx), cy = p3 * (bbar[1][k] - by), cz = p3 * (bbar[2][k] - bz);
        fe[0][k] -= detj[g] * (s[0] * bx + s[3] * by + s[5] * bz + cx);
        fe[1][k] -= detj[g] * (s[3] * bx + s[1] * by + s[4] * bz + cy);
        fe[2][k] -= detj[g] * (s[5] * bx + s[4] * by + s[2] * bz + cz);
      }
      if constexpr (kAns) {
        const double sdev[6] = {s[0] - p3, s[1] - p3, s[2] - p3, s[3], s[4], s[5]};
        double Jinv[9], S[2];
        element::inverse3(Jx[g], Jinv);
        element::ans_conjugate_stress(Jinv, thin, sdev, S);
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < 8; ++k) fe[c][k] -= detj[g] * (S[0] * ans_end[g][0][c][k] + S[1] * ans_end[g][1][c][k]);
      }
    }
    if constexpr (Material::kElementRotation) material.end_element(e);
    if (!(dte > 0) || !std::isfinite(dIE)) {
      record_bad(r, blk.element_id[e], V, true);
      continue;
    }
    erode_cause = time_step_erosion(erode_cause, erode_tsmin, dt, dte);
    if (erode_cause > 0) {
      st.internal_energy[e] += dIE_old;
      r.internal_energy += dIE_old;
      r.bulk_viscous_energy += -0.5 * st.bulk_q[e] * trDbar * V * dt;
      erode_element(st, e, blk.element_id[e], erode_cause, 8, r.eroded, r.eroded_energy, r.eroded_hourglass_energy);
      continue;
    }
    st.internal_energy[e] += dIE;
    r.internal_energy += dIE;
    const double q = bulk_viscosity(rho, Le, c_step, trDbar, q1, q2);
    r.bulk_viscous_energy += -0.5 * (st.bulk_q[e] + q) * trDbar * V * dt;  // trapezoid, as in ELFORM 1
    st.bulk_q[e] = q;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) fe[i][k] += q * V * bbar[i][k];
    scatter(f, conn, fe);
    record_dt(r, blk.element_id[e], dte);
  }
}

}  // namespace

void update_hex8_selective(const model::Model& model, const model::ElementBlock& block, BlockState& state,
                           Index begin, Index end, const double* x, const double* v, double* f, double dt,
                           ChunkResult& result) {
  with_material(model, block, state,
                [&](auto&& material) {
                  if (block.elform == -2)
                    selective<true>(material, model, block, state, begin, end, x, v, f, dt, result);
                  else
                    selective<false>(material, model, block, state, begin, end, x, v, f, dt, result);
                });
}

}  // namespace plyimpact::solver
