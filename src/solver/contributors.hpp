// The registry of force-contributor types, in the order the solver applies them (and history.csv
// lists their columns). Adding a kind of force (an interface law, a new contact) is one class and
// one entry here; the solver's cycle does not change.
#pragma once

#include <memory>
#include <vector>

#include "solver/force_contributor.hpp"
#include "solver/rigid_body.hpp"

namespace plyimpact::solver {

// What a contributor may need when the solver builds it (after the initial element pass).
struct ContributorSetup {
  const model::Model& model;
  std::vector<double>& x;          // positions at t = 0; a contact may move penetrating nodes
  double dt_initial = 0;           // s, first step, TSSFAC applied
  double dt_element = 0;           // s, elements' stable step, no TSSFAC
  RigidBodies* bodies = nullptr;   // null without rigid bodies
  const std::vector<int>& node_body;  // (num_nodes) rigid body index or -1
  const std::vector<std::unique_ptr<ForceContributor>>& contributors;  // the solver's list
};

struct ContributorType {
  model::Subsystem (*describe)(const model::Model& model);  // active or left out, and why
  std::unique_ptr<ForceContributor> (*make)(ContributorSetup& setup);  // called when describe says active
};

const std::vector<ContributorType>& contributor_types();

// The model's subsystems with the contributors' inserted where `check` and summary.json list them.
std::vector<model::Subsystem> subsystems(const model::Model& model);

}  // namespace plyimpact::solver
