#include "solver/impactor_motion.hpp"

#include <algorithm>
#include <sstream>

namespace plyimpact::solver {
namespace {

// The deformable impactor's part, or -1.
int impactor_part(const model::Model& model) {
  for (std::size_t p = 0; p < model.parts.size(); ++p)
    if (model.parts[p].name == "impactor" && !model.blocks[std::size_t(model.parts[p].block)].rigid) return int(p);
  return -1;
}

}  // namespace

model::Subsystem ImpactorMotion::describe(const model::Model& model) {
  if (impactor_part(model) < 0)
    return {"impactor_motion", false,
            "left out: no deformable impactor (a rigid impactor's motion is recorded by its rigid body)"};
  return {"impactor_motion", true,
          "deformable impactor: centre of mass, its velocity and the impactor's kinetic energy in history.csv"};
}

ImpactorMotion::ImpactorMotion(const model::Model& model) {
  const int p = impactor_part(model);
  const auto& conn = model.blocks[std::size_t(model.parts[std::size_t(p)].block)].conn;
  nodes_.assign(conn.begin(), conn.end());
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  for (Index n : nodes_) {
    mass_.push_back(model.mass[std::size_t(n)]);
    total_mass_ += mass_.back();
  }
  // The initial state, for a history row written before the first pass.
  ForceContext initial;
  initial.x = model.X.data();
  initial.v = model.v0.data();
  apply(initial);
}

void ImpactorMotion::apply(const ForceContext& c) {
  std::array<double, 3> mx{0, 0, 0}, mv{0, 0, 0};
  double twice_kinetic = 0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const double* x = &c.x[3 * std::size_t(nodes_[k])];
    const double* v = &c.v[3 * std::size_t(nodes_[k])];
    for (int i = 0; i < 3; ++i) {
      mx[i] += mass_[k] * x[i];
      mv[i] += mass_[k] * v[i];
      twice_kinetic += mass_[k] * v[i] * v[i];
    }
  }
  for (int i = 0; i < 3; ++i) {
    centre_[i] = mx[i] / total_mass_;
    velocity_[i] = mv[i] / total_mass_;
  }
  kinetic_ = 0.5 * twice_kinetic;
}

std::vector<std::string> ImpactorMotion::history_columns() const {
  return {"impactor_x", "impactor_y", "impactor_z", "impactor_vx", "impactor_vy", "impactor_vz", "impactor_kinetic_energy"};
}

void ImpactorMotion::history_values(std::vector<double>& row) const {
  row.insert(row.end(), {centre_[0], centre_[1], centre_[2], velocity_[0], velocity_[1], velocity_[2], kinetic_});
}

}  // namespace plyimpact::solver
