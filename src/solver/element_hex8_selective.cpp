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
#include <algorithm>
#include <cmath>

#include "element/hex8.hpp"
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

template <class Material>
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
      if constexpr (Material::kTotalLagrangian) {
        double Finv[9];
        element::velocity_gradient(Xe, B[g], Finv);
        const double Jg = 1.0 / element::inverse3(Finv, F);
        const double scale = std::cbrt(Jbar / Jg);
        for (double& fij : F) fij *= scale;
        point.F = F;
        point.J = Jbar;
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
                [&](auto&& material) { selective(material, model, block, state, begin, end, x, v, f, dt, result); });
}

}  // namespace plyimpact::solver
