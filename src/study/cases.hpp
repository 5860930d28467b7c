// The cases of a study: the parameter values combined (grid or zip), each case's overrides, its
// folder name (parameter values + a hash of the effective scene) and its completion record
// (case.json). A case is finished when its folder holds case.json with the same hash, a
// summary.json that does not say "interrupted" (a signal ended it) and a history.csv; the hash covers the base scene's text, every override and the
// program version, so editing the scene, the study's `set:` or upgrading the program re-runs it.
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "config/overrides.hpp"
#include "study/study_spec.hpp"

namespace plyimpact::study {

struct Case {
  std::string name;                              // folder name
  std::vector<std::string> values;               // per parameter, the value text
  std::vector<config::SceneOverride> overrides;  // fixed `set:` first, then the parameters
  std::string hash;                              // 16 hex digits
  double pass_distance = std::nan("");           // RunRecord::pass_distance, from the loaded scene
};

/// 64-bit FNV-1a of `text`, as 16 hex digits (a change detector, not a cryptographic hash).
std::string fnv1a_hex(std::string_view text);

/// Every case of the study, in order (the last parameter varies fastest in a grid); none when a
/// parameter has no values (a ballistic-limit search without a sweep).
std::vector<Case> expand_cases(const StudySpec& spec, const std::string& scene_text);

/// The case with one value per parameter (the same folder and hash as expand_cases gives it).
Case make_case(const StudySpec& spec, const std::string& scene_text, const std::vector<ParameterValue>& values);

/// True when `dir` holds the finished run of `c` (see the header comment).
bool case_finished(const Case& c, const std::filesystem::path& dir);

/// Writes dir/case.json (atomically): study, case, hash, program version, scene, overrides,
/// parameter values and `status`.
void write_case_record(const StudySpec& spec, const Case& c, const std::filesystem::path& dir, const std::string& status);

/// Arguments of the child process that runs a case: run SCENE --set k=v ... --threads T -o DIR.
std::vector<std::string> case_arguments(const StudySpec& spec, const Case& c, const std::filesystem::path& dir,
                                        int threads);

}  // namespace plyimpact::study
