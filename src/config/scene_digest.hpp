// Identity of a scene for restarts: a 64-bit FNV-1a digest of the effective scene tree (the file
// with the command-line overrides applied), emitted in canonical YAML without comments and layout,
// and without the keys a continued run may legitimately change: control.termination_time (to
// extend a run), control.max_cycles, control.threads (results do not depend on the thread count)
// and the whole output: section (frame, history and restart intervals). Any other change — a
// material constant, a contact option, the mesh — changes the digest. A mesh read from another
// file is covered by the run's identity (run/restart_dump.hpp), not here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/overrides.hpp"

namespace plyimpact::config {

/// Digest of the scene at `path` with `overrides` applied. Call after load_scene accepted them.
/// @throws InputError when the file cannot be read
std::uint64_t scene_digest(const std::string& path, const std::vector<SceneOverride>& overrides);

/// The scene's values in one canonical line: the same for any comments, layout or flow/block style,
/// different for any changed key or value (every key kept, unlike the digest). A study case's
/// identity (study/cases.cpp), so editing a comment does not run finished cases again.
/// @throws InputError for a YAML syntax error
std::string canonical_scene_text(const std::string& yaml_text, const std::string& file_label);

/// Same from the scene text.
std::uint64_t scene_digest_from_string(const std::string& yaml_text, const std::string& file_label,
                                       const std::vector<SceneOverride>& overrides);

}  // namespace plyimpact::config
