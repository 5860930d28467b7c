#include "contact/rigid_wall.hpp"

#include <cmath>

namespace plyimpact::contact {

void RigidWallConstraint::apply(const double* x, const double* v, double* f, const double* mass, double time,
                                double dt_n1, double dt_next, double dt_prev) {
  const auto& w = wall_;
  // Work of a force F applied at t^n: F dt^n (v^{n-1/2} + v^{n+1/2}) / 2, with dt^n the step over
  // which the velocity update applies it (so that it equals the kinetic energy it removes,
  // m (v^{n+1/2}^2 - v^{n-1/2}^2) / 2, exactly); booked half at each pass. The first half of the
  // previous pass's forces comes here, with the velocity they produced. (Weighting with dt_prev
  // instead lost the whole impulse of nodes already on the wall at t = 0, where dt_prev = 0.)
  (void)dt_prev;
  double work = 0;
  for (std::size_t a = 0; a < active_.size(); ++a)
    for (int d = 0; d < 3; ++d) work += 0.5 * active_f_[3 * a + d] * v[3 * std::size_t(active_[a]) + d] * active_dt_;
  next_active_.clear();
  next_f_.clear();
  normal_force_ = tangential_force_ = 0;
  resultant_ = {0, 0, 0};
  const double* n = w.normal.data();
  // The plane at the predicted time t^{n+2}.
  const double t_pred = time + dt_next;
  double p_pred[3];
  for (int d = 0; d < 3; ++d) p_pred[d] = w.point[d] + w.velocity[d] * t_pred;
  const double vw_n = w.velocity[0] * n[0] + w.velocity[1] * n[1] + w.velocity[2] * n[2];
  if (dt_n1 > 0 && dt_next > 0) {
    for (Index node : w.nodes) {
      const std::size_t i = std::size_t(node);
      const double m = mass[i];
      double vs[3], xs[3];
      for (int d = 0; d < 3; ++d) {
        vs[d] = v[3 * i + d] + dt_n1 * f[3 * i + d] / m;
        xs[d] = x[3 * i + d] + dt_next * vs[d];
      }
      const double gap = (xs[0] - p_pred[0]) * n[0] + (xs[1] - p_pred[1]) * n[1] + (xs[2] - p_pred[2]) * n[2];
      if (gap >= 0) continue;
      // Only nodes that were on the allowed side at t^{n+1} (a node far behind a finite wall's
      // plane is not caught by it).
      const double gap_now = (x[3 * i] - w.point[0] - w.velocity[0] * time) * n[0] +
                             (x[3 * i + 1] - w.point[1] - w.velocity[1] * time) * n[1] +
                             (x[3 * i + 2] - w.point[2] - w.velocity[2] * time) * n[2];
      const double vsn_rel = vs[0] * n[0] + vs[1] * n[1] + vs[2] * n[2] - vw_n;
      if (gap_now < -(std::abs(vsn_rel) * dt_next + 1e-12)) continue;
      if (w.length_u > 0) {
        double a = 0, b = 0;
        for (int d = 0; d < 3; ++d) {
          const double r = x[3 * i + d] - w.point[d] - w.velocity[d] * time;
          a += r * w.u[d];
          b += r * w.v[d];
        }
        if (a < 0 || a > w.length_u || b < 0 || b > w.length_v) continue;
      }
      const double dv_n = -gap / dt_next;  // normal velocity change that lands the node on the wall
      const double fn = m * dv_n / dt_n1;
      double F[3] = {fn * n[0], fn * n[1], fn * n[2]};
      double ft_mag = 0;
      if (w.friction > 0) {
        double vt[3];
        const double vsn = vs[0] * n[0] + vs[1] * n[1] + vs[2] * n[2];
        for (int d = 0; d < 3; ++d) vt[d] = (vs[d] - w.velocity[d]) - (vsn - vw_n) * n[d];
        const double speed = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
        if (speed > 0) {
          ft_mag = std::min(m * speed / dt_n1, w.friction * fn);
          for (int d = 0; d < 3; ++d) F[d] -= ft_mag * vt[d] / speed;
        }
      }
      for (int d = 0; d < 3; ++d) {
        f[3 * i + d] += F[d];
        resultant_[d] += F[d];
        work += 0.5 * F[d] * v[3 * i + d] * dt_n1;  // this pass's force with the velocity before it
      }
      normal_force_ += fn;
      tangential_force_ += ft_mag;
      next_active_.push_back(node);
      next_f_.insert(next_f_.end(), F, F + 3);
    }
  }
  energy_ -= work;
  active_.swap(next_active_);
  active_f_.swap(next_f_);
  active_dt_ = dt_n1;
}

void RigidWallConstraint::visit_state(StateVisitor& visitor) {
  visitor.array("active_nodes", active_);
  visitor.array("active_forces", active_f_);
  visitor.scalar("active_dt", active_dt_);
  visitor.scalar("energy", energy_);
  visitor.scalar("normal_force", normal_force_);
  visitor.scalar("tangential_force", tangential_force_);
  visitor.scalar("resultant", resultant_);
}

}  // namespace plyimpact::contact
