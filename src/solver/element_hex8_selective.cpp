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
// (before the B-bar correction, which thus keeps the mean volume rate) and its transpose, with the
// deviatoric stress, to the forces; and its B-bar averages over each layer of four points (the two
// sides of the mid-surface), not over the element, so that the volume rate of a bending field,
// linear through the thickness, is kept: with the element mean a ply one element thick loses a
// third of its own bending stiffness at zero Poisson's ratio (more where the sides are free to
// expand; tests LaminateBending, CantileverFrequency). The layers still average in the plane.
#include <algorithm>
#include <cmath>

#include "element/hex8.hpp"
#include "element/hex8_ans.hpp"
#include "element/hex8_gauss_lanes.hpp"
#include "element/hex8_lanes.hpp"
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

// Whether the material updates an element's eight points at once (lane = point).
template <class Material>
concept PointLanes = requires(Material& m, const LaneVec<6>& a, LaneVec<6>& b, int (&e)[kLanes]) {
  m.update_points(std::size_t{0}, 0.0, a, a, b, e);
};

// One element's eight points: their kinematics (lanes = points) and what the element sums of them.
struct PointKinematics {
  alignas(64) double Jx[9][kLanes], Jinv[9][kLanes], detj[kLanes];  // end of step
  alignas(64) double L[9][kLanes], D[6][kLanes], trD[kLanes];          // mid-step rates
  double V = 0, trDbar = 0;                                            // element (step, bulk viscosity)
  // The B-bar's layers, each with its points: the element (ELFORM 2), or (ELFORM -2) its two halves,
  // the four points either side of the mid-surface. Their volumes, their sums of det J dN/dx (the
  // layer's mean gradient times its volume), and each point's layer-mean volume rate.
  int layers = 1;
  const int* points[2] = {};
  double V_layer[2] = {};
  alignas(64) double grad_sum[2][3][8];
  alignas(64) double trD_mean[kLanes];
};

// The points of the B-bar's layers (PointKinematics): all eight, or (halves[t]) those of layer 0
// and of layer 1 for the thin direction t.
struct LayerPoints {
  int all[8];
  int halves[3][2][4];
  LayerPoints() {
    for (int g = 0; g < 8; ++g) all[g] = g;
    for (int t = 0; t < 3; ++t) {
      int n[2] = {};
      for (int g = 0; g < 8; ++g) {
        const int side = element::ans_layer(g, t);
        halves[t][side][n[side]++] = g;
      }
    }
  }
};
inline const LayerPoints& layer_points() {
  static const LayerPoints table;
  return table;
}

// dN_k/dx_i at Gauss point g (end of step).
inline void gradients_at(const PointKinematics& k, int g, double (&B)[3][8]) {
  const auto& dN = element::gauss_lane_table().dN;
  for (int i = 0; i < 3; ++i)
    for (int n = 0; n < 8; ++n)
      B[i][n] = k.Jinv[i][g] * dN[0][n][g] + k.Jinv[3 + i][g] * dN[1][n][g] + k.Jinv[6 + i][g] * dN[2][n][g];
}

// Gradients, volume and mid-step rates of the element (xe, ve); false if a point's Jacobian is not
// positive (worst: the smallest det J) or a mid-step Jacobian is singular (worst: V).
template <bool kAns>
bool point_kinematics(const double (&xe)[3][8], const double (&ve)[3][8], double dt, int thin,
                      element::AnsElement& ans, PointKinematics& k, double& worst) {
  element::hex8_gauss_jacobians_lanes(xe, k.Jx);
  element::inverse3_lanes(k.Jx, k.Jinv, k.detj);
  worst = k.detj[0];
  for (int l = 1; l < kLanes; ++l) worst = std::min(worst, k.detj[l]);
  if (!(worst > 0)) return false;
  k.V = element::lane_sum(k.detj);
  if constexpr (kAns) {
    k.layers = 2;
    k.points[0] = layer_points().halves[thin][0];
    k.points[1] = layer_points().halves[thin][1];
  } else {
    k.layers = 1;
    k.points[0] = layer_points().all;
  }
  const int per_layer = 8 / k.layers;
  alignas(64) double A[9][kLanes];  // det J Jinv^T: the gradient sums' weights
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) PLYIMPACT_LANES A[3 * i + c][l] = k.detj[l] * k.Jinv[3 * c + i][l];
  for (int layer = 0; layer < k.layers; ++layer) {
    element::hex8_gauss_gradient_sum(A, k.points[layer], per_layer, k.grad_sum[layer]);
    double v = 0;
    for (int q = 0; q < per_layer; ++q) v += k.detj[k.points[layer][q]];
    k.V_layer[layer] = v;
  }
  alignas(64) double Jv[9][kLanes], Jm[9][kLanes], Jm_inv[9][kLanes], det_mid[kLanes];
  element::hex8_gauss_jacobians_lanes(ve, Jv);
  for (int i = 0; i < 9; ++i) PLYIMPACT_LANES Jm[i][l] = k.Jx[i][l] - 0.5 * dt * Jv[i][l];
  element::inverse3_lanes(Jm, Jm_inv, det_mid);
  for (int l = 0; l < kLanes; ++l)
    if (det_mid[l] == 0) {
      worst = k.V;
      return false;
    }
  for (int a = 0; a < 3; ++a)
    for (int j = 0; j < 3; ++j)
      PLYIMPACT_LANES k.L[3 * a + j][l] =
          Jv[3 * a][l] * Jm_inv[j][l] + Jv[3 * a + 1][l] * Jm_inv[3 + j][l] + Jv[3 * a + 2][l] * Jm_inv[6 + j][l];
  alignas(64) double Wax[3][kLanes];
  element::split_rate_lanes(k.L, k.D, Wax, k.trD);
  alignas(64) double w[kLanes];
  PLYIMPACT_LANES w[l] = k.detj[l] * k.trD[l];
  k.trDbar = element::lane_sum(w) / k.V;
  for (int layer = 0; layer < k.layers; ++layer) {
    double sum = 0;
    for (int q = 0; q < per_layer; ++q) sum += w[k.points[layer][q]];
    for (int q = 0; q < per_layer; ++q) k.trD_mean[k.points[layer][q]] = sum / k.V_layer[layer];
  }
  // ELFORM -2's tied shear, before the B-bar correction, which then keeps the mean volume rate.
  if constexpr (kAns) {
    alignas(64) double dD[6][kLanes];
    ans.rate_change_lanes(Jm, Jv, Jm_inv, dD);
    for (int q = 0; q < 6; ++q) PLYIMPACT_LANES k.D[q][l] += dD[q][l];
  }
  PLYIMPACT_LANES {
    const double correction = (k.trD_mean[l] - (k.D[0][l] + k.D[1][l] + k.D[2][l])) / 3.0;
    k.D[0][l] += correction;
    k.D[1][l] += correction;
    k.D[2][l] += correction;
  }
  return true;
}

// The element's nodal forces of its points' stresses sb (less the ANS part, which the caller adds)
// with the B-bar pressure p3: -sum over the points of det J ((sb - p3 I) B + p3 bbar_layer).
inline void stress_forces(const PointKinematics& k, const LaneVec<6>& sb, const LaneScalar& p3, double (&fe)[3][8]) {
  alignas(64) double T[9][kLanes];  // det J (sb - p3 I) Jinv^T
  PLYIMPACT_LANES {
    const double r[3][3] = {{sb[0][l] - p3[l], sb[3][l], sb[5][l]},
                            {sb[3][l], sb[1][l] - p3[l], sb[4][l]},
                            {sb[5][l], sb[4][l], sb[2][l] - p3[l]}};
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        T[3 * a + c][l] =
            k.detj[l] * (r[a][0] * k.Jinv[3 * c][l] + r[a][1] * k.Jinv[3 * c + 1][l] + r[a][2] * k.Jinv[3 * c + 2][l]);
  }
  alignas(64) double fs[3][8];
  element::hex8_gauss_gradient_sum(T, layer_points().all, 8, fs);
  double pressure[2] = {};  // each layer's sum of det J p3, over its volume
  const int per_layer = 8 / k.layers;
  for (int layer = 0; layer < k.layers; ++layer) {
    for (int q = 0; q < per_layer; ++q) pressure[layer] += k.detj[k.points[layer][q]] * p3[k.points[layer][q]];
    pressure[layer] /= k.V_layer[layer];
  }
  for (int i = 0; i < 3; ++i)
    for (int n = 0; n < 8; ++n) {
      double f = fs[i][n];
      for (int layer = 0; layer < k.layers; ++layer) f += pressure[layer] * k.grad_sum[layer][i][n];
      fe[i][n] = -f;
    }
}

// Point by point, for materials without a lane update: each point's Point (D, spin, F) and stress.
// Returns the erosion code of the first point that failed (0: none).
template <bool kAns, class Material>
int update_points_one_by_one(Material& material, const model::ElementBlock& blk, BlockState& st, Index e,
                             double dt, double dte, const PointKinematics& k, const double (&Xe)[3][8], int thin,
                             const double (&ans_strain)[8][2], std::size_t hsize, const LaneVec<6>& s_old,
                             LaneVec<6>& s) {
  int erode_cause = 0;
  // F-bar's volume ratio: the element's, or (ELFORM -2) the point's layer's.
  double Jbar_pt[8];
  for (int g = 0; g < 8; ++g) Jbar_pt[g] = k.V / blk.volume0[e];
  if constexpr (kAns && Material::kTotalLagrangian) {
    for (int g = 0; g < 8; ++g) {
      const int layer = element::ans_layer(g, thin);
      Jbar_pt[g] = k.V_layer[layer] / blk.layer_volume0[2 * std::size_t(e) + layer];
    }
  }
  for (int g = 0; g < 8; ++g) {
    const double Jbar = Jbar_pt[g];
    double D[6], W[9], sg[6];
    for (int i = 0; i < 6; ++i) D[i] = k.D[i][g], sg[i] = s_old[i][g];
    for (int a = 0; a < 3; ++a)
      for (int j = 0; j < 3; ++j) W[3 * a + j] = 0.5 * (k.L[3 * a + j][g] - k.L[3 * j + a][g]);
    double* h = hsize > 0 ? &st.history[(8 * std::size_t(e) + g) * hsize] : nullptr;
    material::Point point{e, g, dt, D, W};
    point.element_dt = dte;
    double F[9];
    [[maybe_unused]] double dE[6];  // ELFORM -2, total Lagrangian: read by the material below
    if constexpr (Material::kTotalLagrangian) {
      double Bg[3][8], Finv[9];
      gradients_at(k, g, Bg);
      element::velocity_gradient(Xe, Bg, Finv);
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
    const int cause = material.update_point(point, sg, h);
    if (cause > 0 && erode_cause == 0) erode_cause = cause;
    for (int i = 0; i < 6; ++i) s[i][g] = sg[i];
  }
  return erode_cause;
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
    // The next element's point histories (8 x hsize values, 1.9 kB for *MAT_054) are the pass's
    // largest stream; asked for one element ahead (with its stresses) they arrive while this one
    // computes. Asked for in two halves, here and after the kinematics: all 35 lines at once are
    // more misses than the core keeps in flight, and it waits at the prefetches.
    const bool ahead = e + 1 < end;
    const std::size_t next_history = 8 * std::size_t(e + 1) * hsize, half = 4 * hsize;
    if (ahead) {
      for (std::size_t b = 0; b < 48; b += 8) __builtin_prefetch(&st.stress[48 * std::size_t(e + 1) + b]);
      for (std::size_t b = 0; b < half; b += 8) __builtin_prefetch(&st.history[next_history + b]);
    }
    const Index* conn = &blk.conn[8 * std::size_t(e)];
    double xe[3][8], ve[3][8], Xe[3][8];
    gather(x, conn, xe);
    gather(v, conn, ve);
    if constexpr (Material::kTotalLagrangian) gather(X, conn, Xe);
    // ELFORM -2: the tied transverse shear (element/hex8_ans.hpp).
    [[maybe_unused]] const int thin = kAns ? int(blk.thin_axis[e]) : 0;
    element::AnsElement ans;
    double ans_strain[8][2] = {};  // total-Lagrangian materials: the tied Green-Lagrange change
    if constexpr (kAns) {
      ans.begin(xe, ve, dt, thin);
      if constexpr (Material::kTotalLagrangian) element::hex8_ans_green_lagrange(xe, Xe, thin, ans_strain);
    }
    PointKinematics k;
    double worst = 0;
    if (!point_kinematics<kAns>(xe, ve, dt, thin, ans, k, worst)) {
      record_bad(r, blk.element_id[e], worst, std::isnan(worst));
      continue;
    }
    if (ahead)
      for (std::size_t b = (half + 7) / 8 * 8; b < 2 * half; b += 8) __builtin_prefetch(&st.history[next_history + b]);
    const double V = k.V, trDbar = k.trDbar;
    st.volume[e] = V;
    const double rho = rho0 * blk.volume0[e] / V;
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
      for (int a = 0; a < 3; ++a)
        for (int j = 0; j < 3; ++j) {
          alignas(64) double w[kLanes];
          PLYIMPACT_LANES w[l] = k.detj[l] * 0.5 * (k.L[3 * a + j][l] - k.L[3 * j + a][l]);
          Wbar[3 * a + j] = element::lane_sum(w) / V;
        }
      double R[9];
      element::hughes_winget(Wbar, dt, R);
      material.begin_element(e, R, dt, dte);
    }

    // Material update of the eight points.
    double* stress = &st.stress[6 * 8 * std::size_t(e)];  // (point, component)
    alignas(64) double s_old[6][kLanes], s[6][kLanes];
    for (int g = 0; g < 8; ++g)
      for (int i = 0; i < 6; ++i) s_old[i][g] = stress[6 * g + i];
    int erode_cause = 0;  // > 0: a point failed (ErosionCause of the first)
    if constexpr (PointLanes<Material>) {
      int codes[kLanes];
      material.update_points(8 * std::size_t(e), dt, k.D, s_old, s, codes);
      for (int g = 0; g < 8 && erode_cause == 0; ++g) erode_cause = codes[g];
    } else {
      erode_cause =
          update_points_one_by_one<kAns>(material, blk, st, e, dt, dte, k, Xe, thin, ans_strain, hsize, s_old, s);
    }
    if constexpr (Material::kElementRotation) material.end_element(e);
    for (int g = 0; g < 8; ++g)
      for (int i = 0; i < 6; ++i) stress[6 * g + i] = s[i][g];

    // Stress work (trapezoid rule; dIE_old: the previous stress's half, all an eroding element books).
    alignas(64) double w_new[kLanes], w_old[kLanes], p3[kLanes];
    PLYIMPACT_LANES {
      double po = 0, pn = 0;
      for (int i = 0; i < 3; ++i) po += s_old[i][l] * k.D[i][l], pn += s[i][l] * k.D[i][l];
      for (int i = 3; i < 6; ++i) po += 2 * s_old[i][l] * k.D[i][l], pn += 2 * s[i][l] * k.D[i][l];
      w_old[l] = 0.5 * k.detj[l] * po * dt;
      w_new[l] = 0.5 * k.detj[l] * pn * dt;
      p3[l] = (s[0][l] + s[1][l] + s[2][l]) / 3.0;
    }
    const double dIE_old = element::lane_sum(w_old), dIE = dIE_old + element::lane_sum(w_new);

    // Forces (ELFORM -2: s less each point's own covariant shear, plus the tied rows).
    double fe[3][8];
    alignas(64) double sb[6][kLanes];
    if constexpr (kAns)
      ans.stress_for_gradients_lanes(k.Jx, k.Jinv, k.detj, s, p3, sb);
    else
      for (int q = 0; q < 6; ++q) PLYIMPACT_LANES sb[q][l] = s[q][l];
    stress_forces(k, sb, p3, fe);
    if constexpr (kAns) ans.add_tied_forces(fe);
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
    // q V bbar, bbar = the element's mean gradient
    for (int i = 0; i < 3; ++i)
      for (int n = 0; n < 8; ++n) {
        double g = 0;
        for (int layer = 0; layer < k.layers; ++layer) g += k.grad_sum[layer][i][n];
        fe[i][n] += q * g;
      }
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
