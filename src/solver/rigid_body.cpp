#include "solver/rigid_body.hpp"

#include <Eigen/Dense>
#include <cmath>

#include <omp.h>

#include "solver/thread_range.hpp"

namespace plyimpact::solver {

namespace {

using M3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
using V3 = Eigen::Vector3d;

V3 vec(const Vec3& a) { return V3(a[0], a[1], a[2]); }
Vec3 arr(const V3& a) { return {a[0], a[1], a[2]}; }

// omega = I^-1 h with I = R I0 R^T; a degenerate inertia gives zero about its null directions.
V3 angular_velocity(const M3& inertia, const V3& h) {
  const double scale = inertia.trace();
  if (!(std::abs(inertia.determinant()) > 1e-12 * scale * scale * scale)) return V3::Zero();
  return inertia.inverse() * h;
}

// exp([w] dt) by Rodrigues' formula.
M3 rotation(const V3& w, double dt) {
  const double angle = w.norm() * dt;
  if (angle == 0) return M3::Identity();
  const V3 k = w.normalized();
  M3 K;
  K << 0, -k[2], k[1], k[2], 0, -k[0], -k[1], k[0], 0;
  return M3::Identity() + std::sin(angle) * K + (1 - std::cos(angle)) * K * K;
}

}  // namespace

RigidBodies::RigidBodies(const model::Model& model) : model_(model) {
  for (const auto& body : model.rigid_bodies) {
    RigidBodyState s;
    s.x = body.centre;
    s.v = body.velocity;
    s.omega = body.angular_velocity;
    const M3 I0 = Eigen::Map<const M3>(body.inertia.data());
    s.h = arr(I0 * vec(body.angular_velocity));
    std::vector<double> r0;
    for (Index n : body.nodes)
      for (int d = 0; d < 3; ++d) r0.push_back(model.X[3 * std::size_t(n) + d] - body.centre[d]);
    states_.push_back(s);
    r0_.push_back(std::move(r0));
  }
}

double RigidBodies::kinetic_energy() const {
  double ke = 0;
  for (std::size_t b = 0; b < states_.size(); ++b) {
    const auto& s = states_[b];
    ke += 0.5 * model_.rigid_bodies[b].mass * vec(s.v).squaredNorm() + 0.5 * vec(s.omega).dot(vec(s.h));
  }
  return ke;
}

double RigidBodies::step(const double* f, double* x, double* v, double dt_n, double dt_half, bool first,
                         const std::vector<double>& curve_value, double& work) {
  double ke = 0;
  for (std::size_t b = 0; b < states_.size(); ++b) {
    const auto& body = model_.rigid_bodies[b];
    auto& s = states_[b];
    const auto& r0 = r0_[b];
    const M3 R = Eigen::Map<const M3>(s.R.data());
    const M3 I0 = Eigen::Map<const M3>(body.inertia.data());
    const M3 I = R * I0 * R.transpose();
    // Resultant force and moment about the centre of mass at t^n. The nodal loop has already moved
    // the slaved nodes with their old velocity (their inverse mass is zero there): x^n = x - dt v.
    V3 F = V3::Zero(), Mo = V3::Zero();
    const V3 xc = vec(s.x);
    for (std::size_t k = 0; k < body.nodes.size(); ++k) {
      const std::size_t n = std::size_t(body.nodes[k]);
      // Most of a body's nodes carry no force (only those in contact do). Skipping them leaves
      // the sums' bits as they are: adding a zero, or a cross product with a zero force, changes
      // no sum (F and M start at +0), and it saves reading their positions and velocities.
      if (f[3 * n] == 0 && f[3 * n + 1] == 0 && f[3 * n + 2] == 0) continue;
      const V3 fk(f[3 * n], f[3 * n + 1], f[3 * n + 2]);
      F += fk;
      const V3 xn(x[3 * n] - dt_half * v[3 * n], x[3 * n + 1] - dt_half * v[3 * n + 1],
                  x[3 * n + 2] - dt_half * v[3 * n + 2]);
      Mo += (xn - xc).cross(fk);
    }
    s.force = arr(F);
    s.a = arr(F / body.mass);
    // Translation with constraints.
    const V3 v_old = vec(s.v);
    V3 v_new = v_old + dt_n * F / body.mass;
    for (int d = 0; d < 3; ++d) {
      double target = v_new[d];
      if (body.fixed[d]) target = 0;
      if (body.curve[d] >= 0) target = curve_value[body.curve[d]];
      if (target != v_new[d]) {
        const double reaction = body.mass * (target - v_new[d]) / dt_n;
        work += dt_n * reaction * 0.5 * (v_old[d] + target);
        v_new[d] = target;
      }
    }
    // Rotation with constraints (global axes).
    const V3 h_old = vec(s.h), w_old = vec(s.omega);
    V3 h_new = h_old + dt_n * Mo;
    V3 w_new = angular_velocity(I, h_new);
    bool constrained = false;
    for (int d = 0; d < 3; ++d) {
      if (body.fixed[3 + d]) w_new[d] = 0, constrained = true;
      if (body.curve[3 + d] >= 0) w_new[d] = curve_value[body.curve[3 + d]], constrained = true;
    }
    if (constrained) {
      const V3 h_c = I * w_new;
      work += (h_c - h_new).dot(0.5 * (w_old + w_new));  // moment of the constraint x mean angular velocity x dt
      h_new = h_c;
    }
    // Kinetic energy at t^n from the mean of the half-step values.
    const V3 v_mean = first ? v_old : V3(0.5 * (v_old + v_new));
    const V3 h_mean = first ? h_old : V3(0.5 * (h_old + h_new));
    ke += 0.5 * body.mass * v_mean.squaredNorm() + 0.5 * angular_velocity(I, h_mean).dot(h_mean);
    // Update the body and its nodes.
    const M3 R_new = rotation(w_new, dt_half) * R;
    const V3 xc_new = xc + dt_half * v_new;
    // Each node depends on the body alone, so threads may share them (same values, any count).
    const long N = long(body.nodes.size());
    const int threads = placing_threads(N, parallel_, omp_get_max_threads());
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
      const ThreadRange mine = thread_range(N, omp_get_thread_num(), omp_get_num_threads());
      for (long k = mine.begin; k < mine.end; ++k) {
        const std::size_t n = std::size_t(body.nodes[std::size_t(k)]);
        const V3 xn = xc_new + R_new * V3(r0[3 * k], r0[3 * k + 1], r0[3 * k + 2]);
        for (int d = 0; d < 3; ++d) {
          const double x_old = x[3 * n + d] - dt_half * v[3 * n + d];
          v[3 * n + d] = (xn[d] - x_old) / dt_half;
          x[3 * n + d] = xn[d];
        }
      }
    }
    s.v = arr(v_new);
    s.h = arr(h_new);
    s.omega = arr(w_new);
    s.x = arr(xc_new);
    Eigen::Map<M3>(s.R.data()) = R_new;
  }
  return ke;
}

}  // namespace plyimpact::solver
