#include "solver/gravity.hpp"

#include <sstream>

namespace plyimpact::solver {

model::Subsystem Gravity::describe(const model::Model& model) {
  const Vec3& g = model.gravity;
  if (g[0] == 0 && g[1] == 0 && g[2] == 0) return {"gravity", false, "left out: the scene sets no gravity"};
  std::ostringstream d;
  d << "body force m g, g = (" << g[0] << ", " << g[1] << ", " << g[2] << ") m/s^2";
  return {"gravity", true, d.str()};
}

void Gravity::apply(const ForceContext& c) {
  const Vec3& g = model_.gravity;
  const std::size_t n = model_.num_nodes();
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) c.f[3 * i + d] += model_.mass[i] * g[d];
  // The step that led to x moved every node by dt v^{n+1/2}: the work up to t^{n+1}.
  for (std::size_t i = 0; i < n; ++i)
    work_ += c.dt * model_.mass[i] * (g[0] * c.v[3 * i] + g[1] * c.v[3 * i + 1] + g[2] * c.v[3 * i + 2]);
}

void Gravity::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "gravity");
  visitor.scalar("work", work_);
}

}  // namespace plyimpact::solver
