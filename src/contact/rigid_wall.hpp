// Planar rigid wall (*RIGIDWALL_PLANAR), the cheapest contact: a constraint, not a penalty. After
// the force pass at t^{n+1} each slave node's next position is predicted with the current force,
//   v* = v^{n+1/2} + dt^{n+1} f / m,  x* = x^{n+1} + dt^{n+3/2} v*,
// and a node that would end behind the wall gets the normal force that puts it exactly on the
// (moving) wall, f_n = m (d / dt^{n+3/2}) / dt^{n+1} with d its predicted penetration; so a node
// stops on the wall in one step with no penalty spring and no oscillation, as LS-DYNA's rigid
// wall does. Friction: Coulomb, the tangential force removes at most the node's predicted
// tangential velocity relative to the wall and is capped at mu f_n. The wall's work on the nodes
// (trapezoid in time) is reported as rigid-wall energy (RWEN = 2) so the energy balance closes.
#pragma once

#include <vector>

#include "core/state_visitor.hpp"
#include "model/model.hpp"

namespace plyimpact::contact {

class RigidWallConstraint {
 public:
  explicit RigidWallConstraint(const model::RigidWall& wall) : wall_(wall) {}

  // time: t^{n+1}; dt_n1 = dt^{n+1} (force to velocity), dt_next = dt^{n+3/2}; dt_prev = dt^{n+1/2},
  // the step that led to x (unused: the work is weighted with dt_n1). Adds the wall forces to f.
  void apply(const double* x, const double* v, double* f, const double* mass, double time, double dt_n1,
             double dt_next, double dt_prev);

  const model::RigidWall& wall() const { return wall_; }
  double normal_force() const { return normal_force_; }      // N, on the wall (sum over nodes)
  double tangential_force() const { return tangential_force_; }
  Vec3 resultant() const { return resultant_; }              // N, force of the wall on the nodes
  double energy() const { return energy_; }                  // J, energy taken out by the wall
  std::size_t active_nodes() const { return active_.size(); }
  // Run state: the nodes held at the last pass, their forces and step (their work is booked at
  // the next pass), the energy and the last pass's force sums.
  void visit_state(StateVisitor& visitor);

 private:
  const model::RigidWall& wall_;
  std::vector<Index> active_;       // nodes held at the last pass
  std::vector<double> active_f_;    // (num active, 3) their wall forces
  double active_dt_ = 0;            // s, dt^n with which they were applied
  std::vector<Index> next_active_;
  std::vector<double> next_f_;
  double normal_force_ = 0, tangential_force_ = 0, energy_ = 0;
  Vec3 resultant_{0, 0, 0};
};

}  // namespace plyimpact::contact
