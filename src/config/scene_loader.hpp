// Scene loader: reads a scene YAML file into a validated, all-SI config::Scene.
// Every problem (YAML syntax, unknown or missing key, wrong type, bad unit, physically impossible
// value, dangling cross reference) throws plyimpact::InputError with one message of the form
//   <file>:<line>:<col>: <key.path>: <what is wrong>; found <value>; allowed <what is allowed>
// Nothing is written anywhere. Every key of the schema appears in tests/data/scenes/good_full.yaml.
#pragma once

#include <string>
#include <vector>

#include "config/overrides.hpp"
#include "config/scene.hpp"

namespace plyimpact::config {

/// Reads and validates the scene file at `path`, after applying `overrides` (config/overrides.hpp)
/// to its tree. Scene::name = file stem, Scene::file = path.
/// @throws InputError (file cannot be read, or any problem in its content or an override)
Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides = {});

/// Same from text; `file_label` is used in messages, Scene::file and (its stem) Scene::name.
/// @throws InputError
Scene load_scene_from_string(const std::string& yaml_text, const std::string& file_label,
                             const std::vector<SceneOverride>& overrides = {});

}  // namespace plyimpact::config
