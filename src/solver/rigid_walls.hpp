// The scene's planar rigid walls (contact/rigid_wall) as one force contributor. A wall is a
// kinematic constraint that predicts each slave node's next position, so it acts in the
// Constraints phase, once the next step is known; its energy is the work it took out (RWEN = 2).
#pragma once

#include "contact/rigid_wall.hpp"
#include "solver/force_contributor.hpp"
#include "solver/row_lag.hpp"

namespace plyimpact::solver {

class RigidWalls : public ForceContributor {
 public:
  static model::Subsystem describe(const model::Model& model);
  explicit RigidWalls(const model::Model& model);

  std::string name() const override { return "rigid_walls"; }
  Phase phase() const override { return Phase::Constraints; }
  void apply(const ForceContext& context) override;
  std::vector<EnergyName> energy_names() const override { return {{"rigid_wall", "rigidwall_energy", true}}; }
  void energies(std::span<double> out) const override { out[0] = energy_; }
  // Every slave node of every wall: a node erosion frees can still strike a wall.
  void mark_held_nodes(std::vector<char>& held) const override {
    for (const auto& w : walls_)
      for (Index node : w.wall().nodes) held[std::size_t(node)] = 1;
  }
  std::vector<std::string> history_columns() const override;
  void history_values(std::vector<double>& row) const override;
  void visit_state(StateVisitor& visitor) override;

  const std::vector<contact::RigidWallConstraint>& walls() const { return walls_; }

 private:
  std::vector<contact::RigidWallConstraint> walls_;
  double energy_ = 0;  // J, sum over the walls at the last apply
  std::vector<double> columns_;  // scratch: the last pass's force columns
  RowLag row_;                   // the force columns at the history row's time
};

}  // namespace plyimpact::solver
