#include "solver/rigid_body_coupling.hpp"

#include <sstream>

namespace plyimpact::solver {

model::Subsystem RigidBodyCoupling::describe(const model::Model& model) {
  if (model.rigid_bodies.empty())
    return {"rigid_bodies", false, "left out: no MAT_020 part and no rigid impactor in contact"};
  std::ostringstream r;
  for (const auto& b : model.rigid_bodies)
    r << (r.tellp() > 0 ? "; " : "") << b.name << " (" << b.nodes.size() << " nodes, " << b.mass << " kg"
      << (b.part < 0 ? ", surface only" : "") << ")";
  return {"rigid_bodies", true, "6-dof, Rodrigues rotation update; " + r.str()};
}

RigidBodyCoupling::RigidBodyCoupling(const model::Model& model, RigidBodies& bodies, const std::vector<int>& node_body,
                                     const std::vector<std::unique_ptr<ForceContributor>>& contributors)
    : model_(model), bodies_(bodies), node_body_(node_body), contributors_(contributors) {}

void RigidBodyCoupling::apply(const ForceContext& context) {
  last_step_ = context.dt;
  auto& bodies = bodies_.states();
  for (auto& b : bodies) b.contact_force = {0, 0, 0};
  forces_.clear();
  for (const auto& c : contributors_) c->node_forces(forces_);
  for (const auto& nf : forces_) {
    const auto& nodes = *nf.nodes;
    const auto& fc = *nf.forces;
    auto add = [&](std::size_t u) {
      if (const int b = node_body_[nodes[u]]; b >= 0)
        for (int d = 0; d < 3; ++d) bodies[b].contact_force[d] += fc[3 * u + d];
    };
    // The contact lists its nodes with a force (a few hundred of the default scene's 18,784).
    if (nf.loaded)
      for (const Index u : *nf.loaded) add(std::size_t(u));
    else
      for (std::size_t u = 0; u < nodes.size(); ++u) add(u);
  }
  columns_.clear();
  for (const auto& b : bodies) columns_.insert(columns_.end(), b.contact_force.begin(), b.contact_force.end());
  row_.record(columns_, context.dt == 0);
}

std::vector<std::string> RigidBodyCoupling::history_columns() const {
  std::vector<std::string> cols;
  for (const auto& b : model_.rigid_bodies)
    for (const char* q : {"_x", "_y", "_z", "_vx", "_vy", "_vz", "_ax", "_ay", "_az", "_contact_fx", "_contact_fy",
                          "_contact_fz"})
      cols.push_back("rigid_" + b.name + q);
  return cols;
}

void RigidBodyCoupling::history_values(std::vector<double>& row) const {
  // The row is at t^n, the balance's time; after the step a body's centre is at t^{n+1}: step it
  // back by its velocity of that step (exact for the centre's update). v is v^{n+1/2}.
  // The contact force is that of the pass at t^n (row_), not the last one at t^{n+1}.
  const double back = last_step_;
  const auto force = row_.row();
  std::size_t k = 0;
  for (const auto& b : bodies_.states()) {
    row.insert(row.end(), {b.x[0] - back * b.v[0], b.x[1] - back * b.v[1], b.x[2] - back * b.v[2], b.v[0], b.v[1],
                           b.v[2], b.a[0], b.a[1], b.a[2], force[k], force[k + 1], force[k + 2]});
    k += 3;
  }
}

void RigidBodyCoupling::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "rigid_body_coupling");
  visitor.scalar("last_step", last_step_);
  row_.visit_state(visitor);
}

}  // namespace plyimpact::solver
