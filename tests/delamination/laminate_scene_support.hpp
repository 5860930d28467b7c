// Test support for the laminate-interface scene tests: the model of an inline scene (meshed with
// gmsh as `run` does) and the message a bad scene is refused with.
#pragma once

#include <string>

#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"

namespace plyimpact::test {

// `label` names the scene in messages (file:line:col).
inline model::Model build_laminate(const std::string& yaml, const std::string& label) {
  const config::Scene s = config::load_scene_from_string(yaml, label);
  return model::build_model(s, mesh::mesh_scene(s));
}

// The InputError's text, or "(no error)" when the scene builds.
inline std::string laminate_error(const std::string& yaml, const std::string& label) {
  try {
    build_laminate(yaml, label);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace plyimpact::test
