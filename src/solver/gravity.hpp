// Gravity (*LOAD_BODY): f += m g at every node. Its work, sum over steps of dt^{n+1/2} m g . v^{n+1/2}
// (= m g . (x - x0) exactly), is external work in the energy balance.
#pragma once

#include "solver/force_contributor.hpp"

namespace plyimpact::solver {

class Gravity : public ForceContributor {
 public:
  static model::Subsystem describe(const model::Model& model);
  explicit Gravity(const model::Model& model) : model_(model) {}

  std::string name() const override { return "gravity"; }
  void apply(const ForceContext& context) override;
  double external_work() const override { return work_; }
  void visit_state(StateVisitor& visitor) override;

 private:
  const model::Model& model_;
  double work_ = 0;  // J, up to the last apply
};

}  // namespace plyimpact::solver
