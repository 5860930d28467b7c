// Rigid bodies (*MAT_020 parts and the meshed rigid impactor), docs/theory.md section 9. Each body's
// nodes are slaved to it. One cycle, after the nodal update:
//   F = sum f_k,  M = sum r_k x f_k            (f: all forces at t^n, contact included)
//   v_cm^{n+1/2} = v_cm^{n-1/2} + dt^n F / m,   H^{n+1/2} = H^{n-1/2} + dt^n M   (global frame)
//   omega^{n+1/2} = I(t^n)^-1 H^{n+1/2},  I(t) = R I_0 R^T
//   R^{n+1} = exp(dt^{n+1/2} [omega]) R^n       (Rodrigues: exactly orthogonal; |H| is conserved
//                                                 in torque-free motion since H only changes by M)
//   x_cm^{n+1} = x_cm^n + dt^{n+1/2} v_cm^{n+1/2},  x_k^{n+1} = x_cm^{n+1} + R^{n+1} r_k0,
//   v_k^{n+1/2} = (x_k^{n+1} - x_k^n) / dt^{n+1/2}   (consistent with the node positions)
// Fixed dofs (CON1/CON2, rigid_bodies.fix) have zero velocity; prescribed dofs follow their curve,
// and the force (moment) that takes is booked as external work, like a nodal velocity condition.
#pragma once

#include <vector>

#include "core/state_visitor.hpp"
#include "model/model.hpp"

namespace plyimpact::solver {

struct RigidBodyState {
  Vec3 x{0, 0, 0};        // centre of mass at t^n (after a step: t^{n+1})
  Vec3 v{0, 0, 0};        // centre-of-mass velocity at t^{n+1/2}
  Vec3 a{0, 0, 0};        // F / m at t^n (the force of the last step)
  Vec3 h{0, 0, 0};        // angular momentum about the centre of mass at t^{n+1/2}, global
  Vec3 omega{0, 0, 0};    // angular velocity at t^{n+1/2}
  Mat3 R{1, 0, 0, 0, 1, 0, 0, 0, 1};  // rotation from the reference configuration
  Vec3 force{0, 0, 0};    // resultant force at t^n, N
  Vec3 contact_force{0, 0, 0};  // contact part of it (penalty contacts), N
};

class RigidBodies {
 public:
  explicit RigidBodies(const model::Model& model);

  // One cycle; f holds the forces at t^n. curve_value: model curves at t^{n+1/2}. Overwrites x
  // (to t^{n+1}) and v (to t^{n+1/2}) of the slaved nodes. Returns the bodies' kinetic energy at
  // t^n; adds the work of prescribed motion over this step to `work`.
  double step(const double* f, double* x, double* v, double dt_n, double dt_half, bool first,
              const std::vector<double>& curve_value, double& work);

  // Nodes of a body with at least kParallelMinNodes are placed by all threads when on (the
  // solver's choice for the model), thread t the range thread_range(nodes, t, threads) of the
  // body's node list. The resultant stays serial: its sums keep their order.
  static constexpr long kParallelMinNodes = 1024;
  void set_parallel(bool on) { parallel_ = on; }
  // Threads that place a body of `nodes` nodes when nt are available.
  static int placing_threads(long nodes, bool parallel, int nt) {
    return parallel && nodes >= kParallelMinNodes ? nt : 1;
  }

  const std::vector<RigidBodyState>& states() const { return states_; }
  std::vector<RigidBodyState>& states() { return states_; }
  double kinetic_energy() const;  // at the current half step (for the initial balance)
  void visit_state(StateVisitor& visitor) { visitor.fixed_array("bodies", states_); }

 private:
  const model::Model& model_;
  std::vector<RigidBodyState> states_;
  std::vector<std::vector<double>> r0_;  // per body: (num_nodes, 3) reference offsets from x_cm
  bool parallel_ = false;
};

}  // namespace plyimpact::solver
