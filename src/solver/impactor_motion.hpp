// The motion of a deformable impactor (the laminate scene's `impactor:` with rigid: false, a part
// named "impactor") as history columns, so that a study can read its residual velocity and the
// energy it lost as it does a rigid impactor's: centre of mass impactor_{x,y,z} (m), its velocity
// impactor_{vx,vy,vz} (m/s, the mass-weighted mean of the nodal velocities v^{n+1/2}) and the
// impactor's kinetic energy impactor_kinetic_energy (J, every node: translation, spin and
// vibration). It adds no force (Bookkeeping phase) and costs one pass over the impactor's nodes.
#pragma once

#include <array>
#include <vector>

#include "solver/force_contributor.hpp"

namespace plyimpact::solver {

class ImpactorMotion : public ForceContributor {
 public:
  static model::Subsystem describe(const model::Model& model);
  explicit ImpactorMotion(const model::Model& model);

  std::string name() const override { return "impactor_motion"; }
  Phase phase() const override { return Phase::Bookkeeping; }
  void apply(const ForceContext& context) override;
  std::vector<std::string> history_columns() const override;
  void history_values(std::vector<double>& row) const override;

 private:
  std::vector<Index> nodes_;
  std::vector<double> mass_;  // kg per node, as in the model (fixed: erosion leaves the impactor's mass alone)
  double total_mass_ = 0;
  std::array<double, 3> centre_{0, 0, 0}, velocity_{0, 0, 0};
  double kinetic_ = 0;
};

}  // namespace plyimpact::solver
