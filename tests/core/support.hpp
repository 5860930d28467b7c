// Test support: build a model from an inline YAML scene (mass-scaled as `run` does) and step a solver. Tests state their
// physics and tolerances themselves; this only removes boilerplate.
#pragma once

#include <string>

#include "config/scene_loader.hpp"
#include "mesh/mesh.hpp"
#include "model/model.hpp"
#include "solver/mass_scaling.hpp"
#include "solver/solver.hpp"

namespace plyimpact::test {

inline model::Model model_from_yaml(const std::string& yaml, const std::string& label = "inline.yaml") {
  const config::Scene scene = config::load_scene_from_string(yaml, label);
  model::Model model = model::build_model(scene, mesh::mesh_boxes(scene));
  solver::apply_mass_scaling(model);  // control.dt2ms, as the application does after building
  return model;
}

// Runs the solver until time t_end (the last step lands on t_end exactly).
inline void run_until(solver::Solver& s, double t_end) {
  while (s.state().time < t_end * (1 - 1e-14)) {
    auto& st = s.state();
    if (st.time + st.dt_next_half > t_end) st.dt_next_half = t_end - st.time;
    s.step();
  }
}

}  // namespace plyimpact::test
