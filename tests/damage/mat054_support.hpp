// Test support for *MAT_054/055: the seed's data sets and a single material-point driver that
// imposes some strain components and solves the others so that their stresses stay zero.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <vector>

#include "config/mat054_spec.hpp"
#include "material/composite_damage.hpp"
#include "model/material_builder.hpp"

namespace plyimpact::test {

namespace H = material::composite_history;

// T800S/M21 card of the seed's Figure 7.3 (a -45 degree ply; the card is in mm-t-s-MPa), in SI.
inline config::MatCompositeDamage t800_card() {
  config::MatCompositeDamage m;
  m.RO = 1550;
  m.EA = 165e9, m.EB = 7.64e9, m.EC = 7.64e9;
  m.PRBA = 0.0162, m.PRCA = 0.0162, m.PRCB = 0.4;
  m.GAB = 5.61e9, m.GBC = 2.75e9, m.GCA = 5.61e9;
  m.axes.AOPT = 2, m.axes.A = {-0.7071, 0.7071, 0}, m.axes.D = {-0.7071, -0.7071, 0};
  m.DFAILM = 0.0366, m.DFAILS = 0;
  m.SOFT = 1, m.YCFAC = 2, m.DFAILT = 0.0133, m.DFAILC = -0.00727;
  m.XC = 1200e6, m.XT = 2200e6, m.YC = 280e6, m.YT = 45e6, m.SC = 50e6;
  m.CRIT = 54, m.BETA = 1;
  m.SOFT2 = 1, m.SOFTG = 1;
  return m;
}

// The same card with the strains to failure of the seed's Table 8.5, 0 degree column.
inline config::MatCompositeDamage t800_card_0deg() {
  config::MatCompositeDamage m = t800_card();
  m.DFAILT = 0.01557, m.DFAILC = -0.0105, m.DFAILM = 0.0105, m.DFAILS = 0;
  return m;
}

// The card without strain erosion (DFAILT = 0: only fibre-tension failure erodes), to see every
// criterion reached on its own.
inline config::MatCompositeDamage t800_criteria_only() {
  config::MatCompositeDamage m = t800_card();
  m.DFAILT = 0, m.DFAILC = 0, m.DFAILM = 0, m.DFAILS = 0;
  return m;
}

// BMS8-212 of the seed's Table 8.1 (nu_ab = 0.025 there is the minor ratio PRBA; GCA is not given
// and is taken equal to GAB; BETA is not given: 0, the maximum-stress fibre criterion).
inline config::MatCompositeDamage bms8212_card() {
  config::MatCompositeDamage m;
  m.RO = 1548;
  m.EA = 117.9e9, m.EB = 8.825e9, m.EC = 8.825e9;
  m.PRBA = 0.025, m.PRCA = 0.025, m.PRCB = 0.3;
  m.GAB = 5.51e9, m.GBC = 2.53e9, m.GCA = 5.51e9;
  m.axes.AOPT = 2;
  m.XT = 1103e6, m.XC = 1034e6, m.YT = 55e6, m.YC = 250e6, m.SC = 70e6;
  m.DFAILT = 9.35e-3, m.DFAILC = -8.77e-3, m.DFAILM = 0.028, m.DFAILS = 0.03;
  m.CRIT = 54, m.BETA = 0;
  return m;
}

// One integration point driven in the axes of Q (rows: material a, b, c in driver axes); Q = I
// drives it in material axes.
class PointDriver {
 public:
  using V6 = std::array<double, 6>;

  explicit PointDriver(const config::MatCompositeDamage& m, const Eigen::Matrix3d& q = Eigen::Matrix3d::Identity())
      : p_(model::composite_damage_params(m, {"test", 0, 0, "mat"})), q_(q) {
    material::composite_damage_init(p_, h_.data());
  }

  const material::CompositeDamageParams& params() const { return p_; }
  const double* history() const { return h_.data(); }
  double flag(int mode) const { return h_[mode]; }
  material::CompositeDamageContext ctx;

  // Stress and total strain in driver axes (Voigt xx yy zz xy yz zx, engineering shear strain).
  const std::array<double, 6>& stress() const { return sg_; }
  const std::array<double, 6>& strain() const { return eg_; }
  // Stress in material axes.
  const std::array<double, 6>& material_stress() const { return sm_; }
  const material::CompositeDamageResult& result() const { return res_; }

  // One cycle: component i of the strain increment is de[i] where fixed[i], and is solved for
  // where !fixed[i] so that stress component i is zero at the end of the cycle. A small probe
  // (the tangent at the current state) predicts the free increments; Newton
  // steps on full-size probes correct them as long as they stay on the predicted branch (the same
  // mode flags). The response is piecewise linear, so this is exact up to round-off; degenerate
  // directions (a removed component carries no stress whatever its strain) get the minimum-norm
  // solution. Every probe works on a copy of the state.
  // When a mode fails in the cycle the lateral stresses released by the drop are not in balance
  // on the new branch; one more cycle with no imposed increment (free increments only) restores
  // them, as the next explicit cycles would, and is kept only if it lowers the lateral stresses.
  // It counts as a cycle (NCYRED).
  void step(const std::array<double, 6>& de, const std::array<bool, 6>& fixed) {
    const auto before = modes();
    commit(solve_increment(de, fixed));
    if (modes() == before || res_.erode) return;
    double now = 0;
    for (int i = 0; i < 6; ++i)
      if (!fixed[i]) now = std::max(now, std::abs(sg_[i]));
    const V6 relax = solve_increment(V6{}, fixed);
    if (residual(relax, fixed) < now) commit(relax);  // only if it really restores the balance
  }

  // Uniaxial stress along driver axis `axis` (0..2) or pure shear (3..5): imposes the strain
  // increment on that component, every other stress stays zero.
  void uniaxial_step(int axis, double de) {
    std::array<double, 6> d{};
    std::array<bool, 6> fixed{};
    d[axis] = de;
    fixed[axis] = true;
    step(d, fixed);
  }
  // Uniaxial path to the total strain `target` on `axis` in n equal increments.
  void uniaxial_to(int axis, double target, int n) {
    const double de = (target - eg_[axis]) / n;
    for (int k = 0; k < n; ++k) uniaxial_step(axis, de);
  }

 private:

  std::array<double, 5> modes() const {
    return {h_[H::kFibreTension], h_[H::kFibreCompression], h_[H::kMatrixTension], h_[H::kMatrixCompression],
            h_[H::kCause]};
  }

  V6 solve_increment(const V6& de, const std::array<bool, 6>& fixed) const {
    std::vector<int> free;
    double size = 0;
    for (int i = 0; i < 6; ++i) {
      if (!fixed[i]) free.push_back(i);
      else size = std::max(size, std::abs(de[i]));
    }
    V6 d = de;
    for (int i : free) d[i] = 0;
    const auto n = static_cast<Eigen::Index>(free.size());
    // Newton step for the increment `base` probed at `scale` times its size, Jacobian from
    // perturbations `delta` (strain, before scaling). Returns the corrected increment and the
    // residual of `base`.
    auto solve = [&](double scale, const V6& base, double delta) {
      const State s0 = state_after(scaled(base, scale));
      // Free stresses at the end of the full increment, extrapolated linearly from a cycle without
      // increment (which may differ from the current stress: an NCYRED ramp moves on each cycle).
      const V6 still = scale < 1 ? state_after(V6{}).stress : sg_;
      Eigen::VectorXd f(n);
      for (Eigen::Index k = 0; k < n; ++k)
        f[k] = still[free[k]] + (s0.stress[free[k]] - still[free[k]]) / scale;
      // Jacobian on the branch of the base probe: right at a failure surface a perturbation may
      // land on the other side (other mode flags); then the opposite perturbation is used.
      Eigen::MatrixXd J(n, n);
      for (Eigen::Index c = 0; c < n; ++c) {
        for (double sign : {1.0, -1.0}) {
          V6 dp = base;
          dp[free[c]] += sign * delta;
          const State sp = state_after(scaled(dp, scale));
          for (Eigen::Index k = 0; k < n; ++k)
            J(k, c) = (sp.stress[free[k]] - s0.stress[free[k]]) / (scale * sign * delta);
          if (sp.modes == s0.modes) break;
        }
      }
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(J);
      // Genuine singular values are >= ~GBC/C11 ~ 1e-2 of the largest; finite-difference noise of a
      // mechanism direction (removed components) is ~1e-6: drop everything below 1e-4.
      cod.setThreshold(1e-4);
      const Eigen::VectorXd x = cod.solve(-f);
      V6 out = base;
      for (Eigen::Index c = 0; c < n; ++c) out[free[c]] += x[c];
      return std::pair{out, f.cwiseAbs().maxCoeff()};
    };
    if (n > 0) {
      // The prediction probe is at most 1e-8 strain and 1e-3 of the increment, so that next to a
      // failure surface (a 1e-9 bracket leaves ~0.1 Pa) it stays on the current side; Jacobian
      // perturbations are 1e-12 strain (~0.01 Pa, well above the round-off of ~1e8 Pa stresses).
      const double scale = size > 0 ? std::min(1e-3, 1e-8 / size) : 1.0;
      auto residual_of = [&](const V6& x) {
        const State st = state_after(x);
        double r = 0;
        for (int i : free) r = std::max(r, std::abs(st.stress[i]));
        return std::pair{r, st.modes};
      };
      d = solve(scale, d, 1e-12 / scale).first;
      const auto branch = state_after(d).modes;
      // Accept a Newton step only on the predicted branch and if it lowers the residual (a removed
      // component leaves a mechanism the linearisation cannot see).
      for (int it = 0; it < 3; ++it) {
        const auto [next, residual] = solve(1.0, d, 1e-12);
        if (residual < 1e-6) break;  // Pa: far below any check
        const auto [r_next, m_next] = residual_of(next);
        if (m_next != branch || !(r_next < residual)) break;
        d = next;
      }
    }
    return d;
  }

  double residual(const V6& d, const std::array<bool, 6>& fixed) const {
    const State st = state_after(d);
    double r = 0;
    for (int i = 0; i < 6; ++i)
      if (!fixed[i]) r = std::max(r, std::abs(st.stress[i]));
    return r;
  }

  static V6 scaled(V6 v, double f) {
    for (double& x : v) x *= f;
    return v;
  }
  // Driver-axis strain increment -> material axes (tensor rotation, engineering shear at the ends).
  V6 to_material_strain(const V6& e) const {
    Eigen::Matrix3d t;
    t << e[0], e[3] / 2, e[5] / 2, e[3] / 2, e[1], e[4] / 2, e[5] / 2, e[4] / 2, e[2];
    const Eigen::Matrix3d m = q_ * t * q_.transpose();
    return {m(0, 0), m(1, 1), m(2, 2), 2 * m(0, 1), 2 * m(1, 2), 2 * m(2, 0)};
  }
  V6 to_driver_stress(const V6& s) const {
    Eigen::Matrix3d t;
    t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    const Eigen::Matrix3d g = q_.transpose() * t * q_;
    return {g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(2, 0)};
  }
  // Stress (driver axes) and mode flags + erosion after a trial cycle with increment d (driver
  // axes) on a copy of the state.
  struct State {
    V6 stress;
    std::array<double, 5> modes;
  };
  State state_after(const V6& d) const {
    auto h = h_;
    V6 s = sm_;
    const V6 dm = to_material_strain(d);
    material::composite_damage_update(p_, dm.data(), s.data(), h.data(), ctx);
    return {to_driver_stress(s), {h[H::kFibreTension], h[H::kFibreCompression], h[H::kMatrixTension],
                                  h[H::kMatrixCompression], h[H::kCause]}};
  }
  void commit(const V6& d) {
    const V6 dm = to_material_strain(d);
    res_ = material::composite_damage_update(p_, dm.data(), sm_.data(), h_.data(), ctx);
    sg_ = to_driver_stress(sm_);
    for (int i = 0; i < 6; ++i) eg_[i] += d[i];
  }

  material::CompositeDamageParams p_;
  Eigen::Matrix3d q_;
  std::array<double, material::kCompositeDamageHistory> h_{};
  V6 sm_{}, sg_{}, eg_{};
  material::CompositeDamageResult res_{};
};

}  // namespace plyimpact::test
