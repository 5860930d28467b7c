#include "solver/rigid_walls.hpp"

#include <sstream>

namespace plyimpact::solver {

model::Subsystem RigidWalls::describe(const model::Model& model) {
  if (model.rigid_walls.empty()) return {"rigid_walls", false, "left out: the scene defines no rigid wall"};
  std::ostringstream w;
  for (const auto& wall : model.rigid_walls)
    w << (w.tellp() > 0 ? "; " : "") << wall.name << " (" << (wall.length_u > 0 ? "finite" : "infinite") << ", "
      << wall.nodes.size() << " slave nodes" << (wall.friction > 0 ? ", friction" : "") << ")";
  return {"rigid_walls", true, "planar, kinematic constraint; " + w.str()};
}

RigidWalls::RigidWalls(const model::Model& model) {
  for (const auto& w : model.rigid_walls) walls_.emplace_back(w);
}

void RigidWalls::apply(const ForceContext& c) {
  double ew = 0;
  for (auto& w : walls_) {
    w.apply(c.x, c.v, c.f, c.mass, c.time, c.dt_n1, c.dt_next, c.dt);
    ew += w.energy();
  }
  energy_ = ew;
  columns_.clear();
  for (const auto& w : walls_) columns_.insert(columns_.end(), {w.normal_force(), w.tangential_force()});
  row_.record(columns_, c.dt == 0);
}

std::vector<std::string> RigidWalls::history_columns() const {
  std::vector<std::string> cols;
  for (const auto& w : walls_)
    for (const char* q : {"_normal", "_tangential"}) cols.push_back("wall_" + w.wall().name + q);
  return cols;
}

void RigidWalls::history_values(std::vector<double>& row) const {
  row.insert(row.end(), row_.row().begin(), row_.row().end());
}

void RigidWalls::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "rigid_walls");
  visitor.scalar("energy", energy_);
  row_.visit_state(visitor);
  for (std::size_t i = 0; i < walls_.size(); ++i) {
    StateGroup wall(visitor, walls_[i].wall().name);
    walls_[i].visit_state(visitor);
  }
}

}  // namespace plyimpact::solver
