// A study's ballistic-limit search run on real cases (ballistic_limit.hpp has the search and the
// perforation criterion): each velocity the search asks for is a case of the study like any other
// (its folder named by the value and the effective scene's hash, validated before it runs, reused
// when already finished), so an interrupted or repeated search replays its rounds from the
// finished folders and runs only what is missing. The study's finished sweep cases narrow the
// bracket. Results: study.json "ballistic_limit", ballistic_limit.csv (every shot in order) and
// the bracket on the residual-velocity plot.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "config/scene.hpp"
#include "output/json.hpp"
#include "study/ballistic_limit.hpp"
#include "study/case_batch.hpp"
#include "study/cases.hpp"

namespace plyimpact::study {

struct BallisticStudy {
  std::optional<BallisticLimit> result;
  std::string error;  // why the search ended without a limit ("" when it found one)
  std::size_t ran = 0, failed = 0;
};

/// RunRecord::pass_distance of a scene: impactor gap + laminate thickness (m); NaN without both.
double plate_pass_distance(const config::Scene& scene);

/// The text of a bracket-unit velocity as a case value ("143.75 m/s"), 6 significant digits.
std::string velocity_text(const BallisticLimitSpec& spec, double v);

/// Runs the search with `batch`; cases it adds are appended to `cases` (and "" or their failure to
/// `failures`) so that the study table lists them. Never throws for the search's own refusals (a
/// bracket that does not bracket, an undecided or failed case): they go to `error`.
BallisticStudy run_ballistic_search(const StudySpec& spec, const std::string& scene_text, const CaseBatch& batch,
                                    std::vector<Case>& cases, std::vector<std::string>& failures, std::ostream& out);

/// study.json's "ballistic_limit" entry (bracket, limit in the bracket unit and in m/s, criterion,
/// every shot). `unit_system` converts the bracket unit to SI.
output::Json ballistic_json(const BallisticLimitSpec& spec, const BallisticStudy& b, const std::string& unit_system);

/// ballistic_limit.csv: <parameter>,residual_velocity,perforated,case (one row per shot, in order).
std::string ballistic_csv(const BallisticLimitSpec& spec, const BallisticLimit& b);

}  // namespace plyimpact::study
