// ELFORM 1: one-point integration with Flanagan-Belytschko hourglass control (IHQ 1-5) or the
// Belytschko-Bindeman assumed-strain stabilisation (IHQ 6), kLanes elements at a time
// (core/lanes.hpp): gather, centre kinematics (element/hex8_lanes.hpp), stable step, material
// update (material/, via with_material), bulk viscosity, internal and hourglass forces (hourglass/),
// then per element in element order: checks, erosion, stores and the scatter (deterministic).
// A partial last group repeats its last element in the spare lanes and discards them.
// Conventions: b[i][k] = dN_k/dx_i; internal force on node k is -V (sigma - q I) b_k; stresses in
// Voigt xx yy zz xy yz zx.
#include <algorithm>
#include <cmath>

#include "element/hex8_lanes.hpp"
#include "hourglass/assumed_strain.hpp"
#include "hourglass/hourglass.hpp"
#include "hourglass/stiffness.hpp"
#include "hourglass/viscous.hpp"
#include "solver/element_families.hpp"
#include "solver/element_step.hpp"
#include "solver/erosion.hpp"
#include "solver/material_registry.hpp"

namespace plyimpact::solver {

namespace {

// An element whose material lost components in this cycle (material/composite_damage.hpp): its IHQ 6
// moduli become the degraded ones (stored at once: they hold whether or not the element survives the
// pass) and the forces its new increment accumulates on (Qa, lane l) are rescaled; the work of last
// cycle's forces is still booked with the forces the nodes received (Qs).
void follow_lost_components(const model::Model& model, const model::ElementBlock& blk, BlockState& st, Index e,
                            int lost, const double (&Jx)[9][kLanes], int l, double (&Hm)[6][kLanes],
                            double (&Qa)[12][kLanes]) {
  double m_old[6], m_new[6], Q[12];
  for (int i = 0; i < 6; ++i) m_old[i] = Hm[i][l];
  hourglass::assumed_strain_element_moduli(model, blk, std::size_t(e), lost, m_new);
  for (int i = 0; i < 12; ++i) Q[i] = Qa[i][l];
  alignas(64) double Ef[9][kLanes], a[kLanes], b[kLanes], c[kLanes];
  hourglass::element_frame(Jx, l, Ef, a, b, c);
  hourglass::rescale_assumed_strain_forces(Q, m_old, m_new, a[l], b[l], c[l]);
  for (int i = 0; i < 12; ++i) Qa[i][l] = Q[i];
  for (int i = 0; i < 6; ++i) Hm[i][l] = m_new[i], st.hourglass_moduli[6 * std::size_t(e) + i] = m_new[i];
}

template <int IHQ, class Material>
void one_point(Material& material, const model::Model& model, const model::ElementBlock& blk, BlockState& st,
               Index begin, Index end, const double* __restrict x, const double* __restrict v, double* __restrict f,
               double dt, ChunkResult& r) {
  using HG = hourglass::Traits<IHQ>;
  const model::Material& mat = model.materials[blk.material];
  const double rho0 = mat.density, c = mat.wave_speed;
  const double qm = blk.qm, q1 = blk.q1, q2 = blk.q2;
  const double erode_tsmin = model.control.erode_tsmin;

  const std::size_t hsize = std::size_t(mat.history_size());
  for (Index e0 = begin; e0 < end; e0 += kLanes) {
    const int n = int(std::min<Index>(kLanes, end - e0));
    // The next batch's histories, stresses and hourglass forces asked for one batch ahead (they stream through the
    // pass; element_hex8_selective.cpp does the same per element).
    if (e0 + 2 * kLanes <= end) {
      const std::size_t next = std::size_t(e0 + kLanes);
      for (std::size_t b = 0; b < kLanes * hsize; b += 8) __builtin_prefetch(&st.history[next * hsize + b]);
      for (std::size_t b = 0; b < 6 * kLanes; b += 8) __builtin_prefetch(&st.stress[6 * next + b]);
      if (!st.hourglass.empty())
        for (std::size_t b = 0; b < 12 * kLanes; b += 8) __builtin_prefetch(&st.hourglass[12 * next + b]);
    }
    Index elem[kLanes];
    for (int l = 0; l < kLanes; ++l) elem[l] = e0 + std::min(l, n - 1);

    // Gather and centre kinematics.
    alignas(64) double xe[3][8][kLanes], ve[3][8][kLanes];
    element::hex8_gather_lanes(blk.conn.data(), elem, x, v, xe, ve);
    alignas(64) double Jx[9][kLanes], Jv[9][kLanes];
    element::hex8_centroid_jacobians_lanes(xe, ve, Jx, Jv);
    alignas(64) double b[3][8][kLanes], V[kLanes];
    if constexpr (HG::kExactGradient)
      element::hex8_mean_gradient_lanes(xe, b, V);
    else
      element::hex8_centroid_gradient_lanes(Jx, b, V);
    alignas(64) double L[9][kLanes], D[6][kLanes], Wax[3][kLanes], trD[kLanes], rho[kLanes], det_mid[kLanes];
    element::mid_step_velocity_gradient_lanes(Jx, Jv, dt, L, det_mid);
    bool ok[kLanes];  // a valid element (set outside the lane loops: GCC does not vectorise bool lanes)
    for (int l = 0; l < kLanes; ++l) ok[l] = V[l] > 0 && det_mid[l] != 0;
    element::split_rate_lanes(L, D, Wax, trD);
    PLYIMPACT_LANES rho[l] = rho0 * blk.volume0[elem[l]] / V[l];
    // Incremental rotation: every incremental material, and IHQ 4/5 (IHQ 6 works in the element frame).
    alignas(64) double R[9][kLanes];
    if constexpr (!Material::kTotalLagrangian || HG::kStiffness) element::incremental_rotation_lanes(Wax, dt, R);

    // Stable step, before the stress update because the damage material's TFAIL compares it with
    // the initial step. Le: characteristic length V / A_max (step, bulk viscosity).
    alignas(64) double dte[kLanes], Le[kLanes];
    alignas(64) double Qstep[kLanes];  // Q of the step: held one in, this cycle's out (step_q)
    // Wave speed of the element's fastest mode (directional_step.hpp): the step's and the bulk
    // viscosity's, so that the viscosity damps that mode at Q2 (element_step.hpp, bulk_viscosity).
    alignas(64) double c_step[kLanes];
    for (int l = 0; l < kLanes; ++l) Qstep[l] = st.step_q[elem[l]];
    for (int l = 0; l < kLanes; ++l) c_step[l] = st.step_wave_speed.empty() ? c : st.step_wave_speed[elem[l]];
    element::hex8_characteristic_length_lanes(xe, V, Le);
    PLYIMPACT_LANES {
      Qstep[l] = step_q(Le[l], c_step[l], trD[l], q1, q2, Qstep[l]);
      dte[l] = element_time_step(Le[l], c_step[l], Qstep[l]);
    }
    if (!blk.step_scale.empty())  // mass scaling (solver/mass_scaling.hpp)
      for (int l = 0; l < kLanes; ++l) dte[l] *= blk.step_scale[elem[l]];

    // Material update (IHQ 6 follows the components a failing material loses in it).
    constexpr bool kFollowsLoss = HG::kAssumedStrain && requires(const Material& m) { m.lost_components_change(0); };
    alignas(64) double s[6][kLanes], s_old[6][kLanes];
    int erode_cause[kLanes] = {};  // > 0: the material failed (ErosionCause)
    for (int l = 0; l < kLanes; ++l)
      for (int i = 0; i < 6; ++i) s_old[i][l] = st.stress[6 * std::size_t(elem[l]) + i];
    material.update(material::LanePoint{elem, n, ok, dt, D, trD, R, Jx, dte}, s_old, s, erode_cause);

    // Stress work (trapezoid rule) and bulk viscosity (compression only; length Le as the step,
    // see bulk_viscosity), whose work uses the trapezoid rule too, (q_old + q_new)/2, as the force
    // acts over both half steps around it.
    // The *_old halves are the work of the previous cycle's stress (and q, hourglass forces) alone:
    // all an element that erodes in this pass books, because its new forces never reach the nodes
    // (see erosion.hpp, erode_element).
    alignas(64) double dIE[kLanes], dIE_old[kLanes], q[kLanes], dQ[kLanes], dQ_old[kLanes];
    PLYIMPACT_LANES {
      double p_old = 0, p_new = 0;
      for (int i = 0; i < 3; ++i) p_old += 0.5 * s_old[i][l] * D[i][l], p_new += 0.5 * s[i][l] * D[i][l];
      for (int i = 3; i < 6; ++i) p_old += s_old[i][l] * D[i][l], p_new += s[i][l] * D[i][l];
      dIE_old[l] = V[l] * p_old * dt;
      dIE[l] = dIE_old[l] + V[l] * p_new * dt;
    }
    // V^(1/3), the viscous laws' area scale; only they pay for its seven Newton divides (GCC keeps
    // the unused lanes' dependent chain otherwise).
    alignas(64) double cbrtV[kLanes];
    if constexpr (HG::kViscous) element::hex8_cube_root_volume_lanes(Jx, V, cbrtV);
    alignas(64) double q_old[kLanes];
    for (int l = 0; l < kLanes; ++l) q_old[l] = st.bulk_q[elem[l]];
    PLYIMPACT_LANES {
      const double ll = Le[l];
      q[l] = trD[l] < 0 ? rho[l] * ll * (q1 * ll * trD[l] * trD[l] - q2 * c_step[l] * trD[l]) : 0.0;
      dQ_old[l] = -0.5 * q_old[l] * trD[l] * V[l] * dt;
      dQ[l] = dQ_old[l] - 0.5 * q[l] * trD[l] * V[l] * dt;
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

    // Hourglass: shape vectors and rates, then the IHQ's force law.
    alignas(64) double gamma[4][8][kLanes], g[3][4][kLanes], Qh[3][4][kLanes], dHG[kLanes], dHG_old[kLanes];
    element::hex8_hourglass_lanes<HG::kProject>(xe, ve, b, gamma, g);
    alignas(64) double Qs[12][kLanes];    // stored hourglass forces of the previous cycle
    alignas(64) double Qp[3][4][kLanes];  // IHQ 6: new forces in the element frame (stored)
    (void)Qp;
    for (int l = 0; l < kLanes; ++l)
      for (int i = 0; i < 12; ++i) Qs[i][l] = st.hourglass[12 * std::size_t(elem[l]) + i];
    if constexpr (HG::kStiffness) {
      alignas(64) double Mh[kLanes];
      for (int l = 0; l < kLanes; ++l) Mh[l] = st.hourglass_moduli[elem[l]];
      hourglass::stiffness_forces_lanes(qm, Mh, b, V, R, g, Qs, dt, Qh, dHG, dHG_old);
    } else if constexpr (HG::kAssumedStrain) {
      alignas(64) double Hm[6][kLanes], Qa[12][kLanes];
      for (int l = 0; l < kLanes; ++l)
        for (int i = 0; i < 6; ++i) Hm[i][l] = st.hourglass_moduli[6 * std::size_t(elem[l]) + i];
      bool rescaled = false;  // Qa differs from Qs only in a cycle where some lane's material failed
      if constexpr (kFollowsLoss)
        for (int l = 0; l < n; ++l) {
          const int lost = material.lost_components_change(l);
          if (!ok[l] || lost < 0) continue;
          if (!rescaled) std::copy(&Qs[0][0], &Qs[0][0] + 12 * kLanes, &Qa[0][0]);
          rescaled = true;
          follow_lost_components(model, blk, st, elem[l], lost, Jx, l, Hm, Qa);
        }
      hourglass::assumed_strain_forces_lanes(qm, Hm, Jx, V, g, Qs, rescaled ? Qa : Qs, dt, Qp, Qh, dHG, dHG_old);
    } else {
      hourglass::viscous_forces_lanes(qm, c, rho, cbrtV, g, Qs, dt, Qh, dHG, dHG_old);
    }
    hourglass::add_hourglass_forces_lanes(Qh, gamma, fe);

    // Per element: checks, erosion, stores and the scatter (in element order: deterministic).
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
      const int cause = time_step_erosion(erode_cause[l], erode_tsmin, dt, dte[l]);
      if (cause > 0) {
        st.internal_energy[e] += dIE_old[l];
        st.hourglass_energy[e] += dHG_old[l];
        r.internal_energy += dIE_old[l];
        r.hourglass_energy += dHG_old[l];
        r.bulk_viscous_energy += dQ_old[l];
        erode_element(st, e, blk.element_id[e], cause, 1, r.eroded, r.eroded_energy, r.eroded_hourglass_energy);
        continue;
      }
      st.internal_energy[e] += dIE[l];
      st.hourglass_energy[e] += dHG[l];
      r.internal_energy += dIE[l];
      r.hourglass_energy += dHG[l];
      material.commit(e, l);
      st.volume[e] = V[l];
      for (int i = 0; i < 6; ++i) st.stress[6 * std::size_t(e) + i] = s[i][l];
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 4; ++a)
          st.hourglass[12 * std::size_t(e) + 4 * i + a] = HG::kAssumedStrain ? Qp[i][a][l] : Qh[i][a][l];
      st.bulk_q[e] = q[l];
      st.step_q[e] = Qstep[l];
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

template <class Material>
void with_hourglass(Material& material, const model::Model& model, const model::ElementBlock& blk, BlockState& st,
                    Index begin, Index end, const double* x, const double* v, double* f, double dt, ChunkResult& r) {
  switch (blk.ihq) {
    case 1: return one_point<1>(material, model, blk, st, begin, end, x, v, f, dt, r);
    case 2: return one_point<2>(material, model, blk, st, begin, end, x, v, f, dt, r);
    case 3: return one_point<3>(material, model, blk, st, begin, end, x, v, f, dt, r);
    case 4: return one_point<4>(material, model, blk, st, begin, end, x, v, f, dt, r);
    case 6: return one_point<6>(material, model, blk, st, begin, end, x, v, f, dt, r);
    default: return one_point<5>(material, model, blk, st, begin, end, x, v, f, dt, r);
  }
}

}  // namespace

void update_hex8_one_point(const model::Model& model, const model::ElementBlock& block, BlockState& state,
                           Index begin, Index end, const double* x, const double* v, double* f, double dt,
                           ChunkResult& result) {
  with_material(model, block, state, [&](auto&& material) {
    with_hourglass(material, model, block, state, begin, end, x, v, f, dt, result);
  });
}

}  // namespace plyimpact::solver
