// A priori stiffness range and stable step of the penalty springs a segment set can form under a
// penalty law: for `check`, the set-up warning and the summary (the run itself uses the Gershgorin
// bound of the springs actually active, penalty_contact).
#pragma once

#include <limits>
#include <vector>

#include "contact/penalty_law.hpp"
#include "contact/segment_set.hpp"

namespace plyimpact::contact {

struct StiffnessBounds {
  double k_min = 0, k_max = 0;  // N/m over possible node-segment pairs
  // Stable step of the stiffest single node-segment spring, 2 / omega (no TSSFAC).
  double dt_stable = std::numeric_limits<double>::infinity();
};

// mass: the model's nodal masses (kg).
StiffnessBounds stiffness_bounds(const SegmentSet& set, const PenaltyLaw& law, const std::vector<double>& mass);

}  // namespace plyimpact::contact
