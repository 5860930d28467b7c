// What mass scaling (*CONTROL_TIMESTEP DT2MS < 0, solver/mass_scaling) added to the model, per part
// and in total, for `check`, summary.json and the warnings. Filled once before the run.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"

namespace plyimpact::model {

struct PartAddedMass {
  int part = 0;             // index into Model::parts
  double mass = 0;          // kg, the part's physical mass (sum of rho V0 of its elements)
  double added = 0;         // kg, the mass added to its elements' nodes
  Index scaled_elements = 0;  // elements whose step was below the target
  double fraction() const { return mass > 0 ? added / mass : 0.0; }
};

struct MassScalingReport {
  bool applied = false;     // true once solver::apply_mass_scaling has run on the model
  double target = 0;        // s, |DT2MS|: the smallest element step (before TSSFAC) after scaling
  std::vector<PartAddedMass> parts;  // deformable parts, in part order
  double total_mass = 0;    // kg, the whole model (rigid bodies included: LS-DYNA's ENDMAS basis)
  double total_added = 0;   // kg
  std::vector<std::string> warnings;  // parts above the warning fraction
  double total_fraction() const { return total_mass > 0 ? total_added / total_mass : 0.0; }
  double deformable_mass() const {
    double m = 0;
    for (const auto& p : parts) m += p.mass;
    return m;
  }
};

}  // namespace plyimpact::model
