// Which parts of the solver a scene switches on, and why the others are left out. The same list is
// printed by `plyimpact check` and written to summary.json, so a user sees at once that, say, a
// scene with no contact builds no contact search. This is the model-level part; the force
// contributors (contact, walls, rigid bodies, gravity) describe themselves (solver::subsystems).
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"

namespace plyimpact::model {

struct Subsystem {
  std::string name;
  bool active = false;
  std::string detail;  // what is active, or why it is left out
};

std::vector<Subsystem> subsystems(const Model& model);

// control.termination_contact's rule in words (check, the run's end line, summary.json).
std::string describe_termination_contact(const config::TerminationContactSpec& spec);

}  // namespace plyimpact::model
