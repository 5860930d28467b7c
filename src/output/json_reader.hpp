// Strict JSON reader (RFC 8259) for the files this program writes and reads back: a run's
// summary.json, a study's case records. Everything outside the grammar is refused rather than
// guessed at: comments, trailing commas, single quotes, leading zeros, NaN/Infinity, duplicate
// keys, control characters inside strings, anything after the value. Numbers without a fraction
// or exponent that fit an int64 (or uint64) stay integers; others are doubles. \uXXXX escapes
// (surrogate pairs included) become UTF-8. Nesting deeper than 256 levels is refused.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "output/json.hpp"

namespace plyimpact::output {

/// Parses `text`; `label` names the source in messages ("<label>:<line>:<col>: <what>").
/// @throws InputError on any deviation from the grammar
Json parse_json(std::string_view text, const std::string& label);

/// Reads and parses the file at `path` (messages name the path).
/// @throws InputError when the file cannot be read or is not valid JSON
Json read_json_file(const std::filesystem::path& path);

}  // namespace plyimpact::output
