// Rigid bodies (solver/rigid_body) seen as a force contributor. The solver integrates the bodies
// in its node update (their nodes carry no mass there); this contributor does the rest: after the
// other contributors it books the contact forces on each body's nodes as the body's contact force,
// and it reports the bodies' history columns (centre, velocity, acceleration, contact force).
#pragma once

#include <memory>

#include "solver/force_contributor.hpp"
#include "solver/rigid_body.hpp"
#include "solver/row_lag.hpp"

namespace plyimpact::solver {

class RigidBodyCoupling : public ForceContributor {
 public:
  static model::Subsystem describe(const model::Model& model);
  // bodies: the solver's; node_body: (num_nodes) body index or -1; contributors: the solver's list,
  // read at every apply for their contact forces.
  RigidBodyCoupling(const model::Model& model, RigidBodies& bodies, const std::vector<int>& node_body,
                    const std::vector<std::unique_ptr<ForceContributor>>& contributors);

  std::string name() const override { return "rigid_bodies"; }
  Phase phase() const override { return Phase::Bookkeeping; }
  void apply(const ForceContext& context) override;
  std::vector<std::string> history_columns() const override;
  void history_values(std::vector<double>& row) const override;
  void visit_state(StateVisitor& visitor) override;

 private:
  const model::Model& model_;
  RigidBodies& bodies_;
  const std::vector<int>& node_body_;
  const std::vector<std::unique_ptr<ForceContributor>>& contributors_;
  std::vector<NodeForces> forces_;  // scratch, reused
  double last_step_ = 0;            // s, Delta t^{n+1/2} of the last pass (history rows are at t^n)
  std::vector<double> columns_;     // scratch: the bodies' contact forces of the last pass
  RowLag row_;                      // those at the history row's time
};

}  // namespace plyimpact::solver
