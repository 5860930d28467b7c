// Command-line changes to a scene: `--set key.path=value` and `--threads N`. An override edits the
// scene's YAML tree before the scene is read, so its value goes through the scene's own units and
// validation (`--set impactor.velocity="5 m/s"`, or a plain number in the scene's unit system), and
// a key the scene format does not have is refused exactly as in a file. Every message about a
// value an override supplied names the override instead of a file line, e.g.
//   --set control.tsfac=0.8: control.tsfac: unknown key 'tsfac' (did you mean 'tssfac'?); ...
// Key paths: names separated by '.', list items by index or by their `name:` (`contacts[0].SOFT`,
// `contacts[impact].SOFT`, `contacts.0.SOFT`). The value is YAML: a number, '<number> <unit>', a
// name, [a, b, c] or {k: v}. Missing intermediate sections are created (`output.interval` when the
// scene has no `output:`) and then validated like any section.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace plyimpact::config {

struct SceneOverride {
  std::string key_path;  // "impactor.velocity", "contacts[0].SOFT"
  std::string value;     // YAML text
  std::string origin;    // how the user wrote it, for messages: "--set impactor.velocity=5 m/s"
};

/// "key.path=value" (the word after --set) -> override.
/// @throws InputError when there is no '=' or the key path is empty or malformed
SceneOverride parse_set_argument(std::string_view text);

/// `--threads N` as the override of control.threads (validated by the scene loader).
SceneOverride threads_override(std::string_view count);

}  // namespace plyimpact::config
