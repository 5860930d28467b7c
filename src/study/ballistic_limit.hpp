// Ballistic limit by bracketing: the impact velocity that separates perforation from arrest,
// searched between a bracket [lo, hi] the user gives (lo must stop the impactor, hi perforate) and
// narrowed until hi - lo <= tolerance. Each round runs `points` velocities evenly spaced inside the
// bracket side by side (one per job: plain bisection with one job, a bracket cut in three with two)
// and keeps the sub-interval where the outcome changes. The search assumes a single change from
// arrest to perforation; a stopped case above a perforating one (a zone of mixed results, as in
// real V50 tests) is reported in the result's notes, and the bracket kept is the one below the
// lowest perforation. The reported limit is the bracket's mid-point, +- half its width.
//
// Perforation criterion of one run (classify()): perforated when, at the end of the run,
//   1. the impactor's velocity along the impact direction is positive (residual velocity > 0),
//   2. its centre of mass has travelled at least `pass_distance` = gap + plate thickness (its
//      undeformed nose is beyond the rear face of the undeformed plate), and
//   3. it flies free: its centre-of-mass velocity changed by less than 1 % of the impact
//      velocity over the last tenth of the run (the plate no longer holds it back: an impactor that
//      is being arrested loses far more; one that has broken through may still brush debris);
// stopped when its velocity along the impact direction reached zero at some time (arrested or
// rebounding: an impactor at rest has no energy left to perforate with, and a plate that springs
// back and carries it forward again does not make it a perforation); otherwise undecided (still
// moving forward in contact with the plate: the run is too short to tell), which ends the search
// with a request for a longer control.termination_time rather than a guess.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "study/quantities.hpp"

namespace plyimpact::study {

enum class Perforation { perforated, stopped, undecided };

/// The criterion in one sentence, for study.json and docs.
extern const char* const kPerforationCriterion;

/// "perforated", "stopped" or "undecided".
const char* perforation_name(Perforation p);

/// The criterion above on one run; `pass_distance` in m. @throws NotAvailable (no impactor motion
/// columns, no pass distance)
Perforation classify(const RunRecord& r, double pass_distance);

/// One evaluated impact velocity.
struct Shot {
  double velocity = 0;  // in the bracket's unit
  double residual = 0;  // m/s along the impact direction
  Perforation state = Perforation::undecided;
  std::string case_name;  // the case folder, "" for an injected evaluation
};

/// Runs the impacts at the given velocities (bracket unit) and returns their shots in that order.
/// A case that fails to run throws (InputError) and ends the search.
using ShotFunction = std::function<std::vector<Shot>(const std::vector<double>&)>;

struct BracketSearch {
  double lo = 0, hi = 0;  // the bracket given (bracket unit)
  double tolerance = 0;   // stop when hi - lo <= tolerance
  int points = 1;         // velocities per round (>= 1)
  std::string origin;     // "study.yaml:12:3: ballistic_limit.bracket", for messages
};

struct BallisticLimit {
  double lo = 0, hi = 0;     // final bracket: lo stopped, hi perforated
  double limit = 0;          // (lo + hi) / 2, reached when hi - lo <= tolerance
  int rounds = 0;            // rounds after the bracket's two ends
  std::vector<Shot> shots;   // every evaluation in order (the two ends first)
  std::vector<std::string> notes;
};

/// The search. `known` shots (a sweep's finished cases) narrow the bracket once its two ends are
/// confirmed, so a sweep followed by a search runs only the rounds the sweep cannot answer.
/// @throws InputError when the bracket does not bracket (lo perforates or hi does not), or a case
/// is undecided; the message names `origin`.
BallisticLimit search_ballistic_limit(const BracketSearch& search, const ShotFunction& shoot,
                                      const std::vector<Shot>& known = {});

}  // namespace plyimpact::study
