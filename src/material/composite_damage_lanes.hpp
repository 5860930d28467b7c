// *MAT_054 / *MAT_055 update of the element pass. The stress is kept in global axes; the material
// axes Q (rows a, b, c) rotate with the element, Q_new = Q_old R^T. At a point: rotate the stress
// into the old axes, the strain increment D dt into the new ones (engineering shear for
// composite_damage_update), update in material axes, rotate back with Q_new. ELFORM 1 rotates the
// axes with the point's R; a multi-point family gives the element's one rotation (kElementRotation:
// a ply has one orientation per element) through begin_element.
#pragma once

#include <algorithm>
#include <cstddef>

#include "material/composite_damage.hpp"
#include "material/composite_damage_intact_lanes.hpp"
#include "material/erosion_neighbourhood.hpp"
#include "material/lane_point.hpp"

namespace plyimpact::material {

// One point: see above. history: kCompositeDamageHistory values. Out of line: it is called per
// point and the damage update it wraps is out of line anyway.
CompositeDamageResult composite_point_update(const CompositeDamageParams& p, const double Qo[9], const double Qn[9],
                                             const double D[6], double dt, const CompositeDamageContext& ctx,
                                             double s[6], double* history);

// Q_new = Q_old R^T (row-major).
inline void rotate_axes(const double Qo[9], const double R[9], double Qn[9]) {
  for (int a = 0; a < 3; ++a)
    for (int j = 0; j < 3; ++j) Qn[3 * a + j] = Qo[3 * a] * R[3 * j] + Qo[3 * a + 1] * R[3 * j + 1] + Qo[3 * a + 2] * R[3 * j + 2];
}

class CompositeDamageLanes {
 public:
  static constexpr bool kTotalLagrangian = false;
  static constexpr bool kElementRotation = true;  // multi-point families call begin_element
  static constexpr bool kIncremental = true;
  // history: (elements * points, kCompositeDamageHistory); axes: (elements, 9) current axes;
  // initial_dt: (elements) element step at t = 0 (TFAIL ratio); erosion_scale: (elements) factor on
  // the erosion strains (CompositeDamageContext), or null for 1; neighbourhood: erosion_nonlocal's
  // neighbourhoods and strain buffers (null start: none), whose `write` receives each updated
  // element's mean strain over its `points`; erosion_base + cause is reported.
  CompositeDamageLanes(const CompositeDamageParams& p, double* history, double* axes, const double* initial_dt,
                       const double* erosion_scale, const ErosionNeighbourhoodView& neighbourhood, int points,
                       int erosion_base)
      : p_(p), history_(history), axes_(axes), initial_dt_(initial_dt), erosion_scale_(erosion_scale),
        neighbourhood_(neighbourhood), points_(points), base_(erosion_base),
        intact_lanes_(composite_intact_lanes_apply(p)) {}

  PLYIMPACT_LANE_KERNEL void update(const LanePoint& p, const LaneVec<6>& s_old, LaneVec<6>& s, int (&erode)[kLanes]) {
    if (!intact_lanes_) {
      for (int l = 0; l < kLanes; ++l) {
        lost_change_[l] = -1;
        mean_limits_[l] = l < p.n && p.ok[l] ? mean_limits(p.elem[l]) : 0;
        update_lane(p, s_old, s, erode, l);
      }
      return;
    }
    // Intact points in SIMD lanes (composite_damage_intact_lanes.hpp); a lane that is not intact or
    // meets a criterion or an erosion limit in this cycle takes the general update.
    alignas(64) double Qo[9][kLanes], intact[kLanes];
    IntactLaneHistory h;
    for (int l = 0; l < kLanes; ++l) {
      const Index e = p.elem[l];
      const double* hl = &history_[std::size_t(e) * kCompositeDamageHistory];
      for (int i = 0; i < 9; ++i) Qo[i][l] = axes_[9 * std::size_t(e) + i];
      for (int i = 0; i < 6; ++i) h.eps[i][l] = hl[composite_history::kStrain + i];
      h.XT[l] = hl[composite_history::kXT], h.XC[l] = hl[composite_history::kXC];
      h.crashfront[l] = hl[composite_history::kCrashfront];
      h.shear_damage[l] = hl[composite_history::kTransverseShearDamage];
      h.element_dt[l] = p.dt > 0 ? p.element_dt[l] : 0.0;
      h.initial_dt[l] = initial_dt_[e];
      h.erosion_scale[l] = scale(e);
      mean_limits_[l] = l < p.n && p.ok[l] ? mean_limits(e) : 0;
      intact[l] = composite_damage_intact(hl) && mean_limits_[l] == 0 ? 1.0 : 0.0;
    }
    IntactLaneResult r;
    composite_intact_lanes(p_, Qo, p.R, s_old, p.D, p.dt, h, r);
    for (int l = 0; l < kLanes; ++l) {
      lost_change_[l] = -1;
      if (l >= p.n || !p.ok[l] || intact[l] == 0 || r.event[l] != 0) {
        update_lane(p, s_old, s, erode, l);
        continue;
      }
      double* hl = &history_[std::size_t(p.elem[l]) * kCompositeDamageHistory];
      for (int i = 0; i < 6; ++i) hl[composite_history::kStrain + i] = r.eps[i][l];
      for (int m = 0; m < 4; ++m) hl[composite_history::kCriteria + m] = r.criteria[m][l];
      for (int i = 0; i < 6; ++i) s[i][l] = r.s[i][l];
      for (int i = 0; i < 9; ++i) qnew_[i][l] = r.Qn[i][l];
    }
  }
  // After update: the in-plane components lane l's point has lost (composite_damage_lost_components)
  // if that set changed in this cycle, else -1 (an intact lane never changes it).
  int lost_components_change(int l) const { return lost_change_[l]; }
  // The rotated axes of a surviving lane become the element's.
  void commit(Index e, int l) {
    for (int i = 0; i < 9; ++i) axes_[9 * std::size_t(e) + i] = qnew_[i][l];
    record_strain(e);
  }

  // Multi-point families: the element's rotation R (from its mean spin) before its points, the
  // axes stored at once (also for an element that erodes, as its stress is zero from then on).
  void begin_element(Index e, const double R[9], double dt, double element_dt) {
    std::copy_n(&axes_[9 * std::size_t(e)], 9, qo_);
    std::copy_n(R, 9, r_);
    rotate_axes(qo_, R, qn_);
    ctx_ = CompositeDamageContext{};
    ctx_.element_dt = dt > 0 ? element_dt : 0.0;
    ctx_.initial_dt = initial_dt_[e];
    ctx_.erosion_scale = scale(e);
    ctx_.mean_limits = mean_limits(e);
  }
  int update_point(const Point& p, double s[6], double* history) const {
    const auto res = composite_point_update(p_, qo_, qn_, p.D, p.dt, ctx_, s, history);
    return res.erode ? base_ + res.cause : 0;
  }
  void end_element(Index e) {
    std::copy_n(qn_, 9, &axes_[9 * std::size_t(e)]);
    record_strain(e);
  }

  // Multi-point families, after begin_element: the element's kLanes points at once (lane = point,
  // history rows points_base + lane): intact points in SIMD lanes, the others by the general
  // update, as update does for one-point elements. Writes each point's erosion code (0: alive).
  PLYIMPACT_LANE_KERNEL void update_points(std::size_t points_base, double dt, const LaneVec<6>& D,
                                           const LaneVec<6>& s_old, LaneVec<6>& s, int (&erode)[kLanes]) {
    bool intact[kLanes] = {};
    IntactLaneResult r;
    if (intact_lanes_) {
      alignas(64) double Qo[9][kLanes], R[9][kLanes];
      IntactLaneHistory h;
      for (int i = 0; i < 9; ++i)
        for (int l = 0; l < kLanes; ++l) Qo[i][l] = qo_[i], R[i][l] = r_[i];
      for (int l = 0; l < kLanes; ++l) {
        const double* hl = &history_[(points_base + l) * kCompositeDamageHistory];
        for (int i = 0; i < 6; ++i) h.eps[i][l] = hl[composite_history::kStrain + i];
        h.XT[l] = hl[composite_history::kXT], h.XC[l] = hl[composite_history::kXC];
        h.crashfront[l] = hl[composite_history::kCrashfront];
        h.shear_damage[l] = hl[composite_history::kTransverseShearDamage];
        h.element_dt[l] = ctx_.element_dt;
        h.initial_dt[l] = ctx_.initial_dt;
        h.erosion_scale[l] = ctx_.erosion_scale;
        intact[l] = composite_damage_intact(hl) && ctx_.mean_limits == 0;
      }
      composite_intact_lanes(p_, Qo, R, s_old, D, dt, h, r);
    }
    for (int l = 0; l < kLanes; ++l) {
      double* hl = &history_[(points_base + l) * kCompositeDamageHistory];
      erode[l] = 0;
      if (intact[l] && r.event[l] == 0) {
        for (int i = 0; i < 6; ++i) hl[composite_history::kStrain + i] = r.eps[i][l];
        for (int m = 0; m < 4; ++m) hl[composite_history::kCriteria + m] = r.criteria[m][l];
        for (int i = 0; i < 6; ++i) s[i][l] = r.s[i][l];
        continue;
      }
      double sl[6], Dl[6];
      for (int i = 0; i < 6; ++i) sl[i] = s_old[i][l], Dl[i] = D[i][l];
      const auto res = composite_point_update(p_, qo_, qn_, Dl, dt, ctx_, sl, hl);
      for (int i = 0; i < 6; ++i) s[i][l] = sl[i];
      if (res.erode) erode[l] = base_ + res.cause;
    }
  }

 private:
  double scale(Index e) const { return erosion_scale_ ? erosion_scale_[e] : 1.0; }
  // The card's limits the mean strain over element e's neighbourhood reached in the previous pass
  // (0 without a neighbourhood, or when no element of it passed one: the mean then cannot).
  int mean_limits(Index e) const {
    if (!neighbourhood_.has(e) || !neighbourhood_.any_past_card(e)) return 0;
    double mean[6];
    neighbourhood_.mean(e, mean);
    return composite_damage_strain_limits(p_, mean, 1.0);
  }
  // The element's mean strain over its points, and whether it passed a card limit, for the
  // neighbourhoods' erosion checks in the next pass.
  void record_strain(Index e) const {
    if (neighbourhood_.write == nullptr) return;
    double* out = neighbourhood_.write + kErosionStrainStride * std::size_t(e);
    const double* h = &history_[std::size_t(e) * std::size_t(points_) * kCompositeDamageHistory];
    for (int i = 0; i < 6; ++i) out[i] = 0;
    for (int g = 0; g < points_; ++g)
      for (int i = 0; i < 6; ++i) out[i] += h[std::size_t(g) * kCompositeDamageHistory + composite_history::kStrain + i];
    for (int i = 0; i < 6; ++i) out[i] /= points_;
    out[kErosionStrainPastCard] = composite_damage_strain_limits(p_, out, 1.0) != 0 ? 1.0 : 0.0;
  }
  // The general point update of lane l (composite_point_update).
  void update_lane(const LanePoint& p, const LaneVec<6>& s_old, LaneVec<6>& s, int (&erode)[kLanes], int l) {
    for (int i = 0; i < 6; ++i) s[i][l] = 0;
    if (l >= p.n || !p.ok[l]) return;
    const Index e = p.elem[l];
    double* h = &history_[std::size_t(e) * kCompositeDamageHistory];
    const int lost_before = composite_damage_lost_components(h);
    const double* Qo = &axes_[9 * std::size_t(e)];
    double Qn[9], Rl[9];
    for (int i = 0; i < 9; ++i) Rl[i] = p.R[i][l];
    rotate_axes(Qo, Rl, Qn);
    double sl[6], Dl[6];
    for (int i = 0; i < 6; ++i) sl[i] = s_old[i][l], Dl[i] = p.D[i][l];
    CompositeDamageContext ctx;
    ctx.element_dt = p.dt > 0 ? p.element_dt[l] : 0.0;
    ctx.initial_dt = initial_dt_[e];
    ctx.erosion_scale = scale(e);
    ctx.mean_limits = mean_limits_[l];
    const auto res = composite_point_update(p_, Qo, Qn, Dl, p.dt, ctx, sl, h);
    const int lost = composite_damage_lost_components(h);
    if (lost != lost_before) lost_change_[l] = lost;
    for (int i = 0; i < 6; ++i) s[i][l] = sl[i];
    for (int i = 0; i < 9; ++i) qnew_[i][l] = Qn[i];
    if (res.erode) erode[l] = base_ + res.cause;
  }

  const CompositeDamageParams& p_;
  double* history_;
  double* axes_;
  const double* initial_dt_;
  const double* erosion_scale_;
  ErosionNeighbourhoodView neighbourhood_;
  int points_;
  int base_;
  bool intact_lanes_;
  int lost_change_[kLanes] = {};
  int mean_limits_[kLanes] = {};
  alignas(64) double qnew_[9][kLanes] = {};
  double qo_[9] = {}, qn_[9] = {}, r_[9] = {};
  CompositeDamageContext ctx_;
};

}  // namespace plyimpact::material
