// The per-element hourglass moduli the solver computes once at t = 0: IHQ 4/5
// (hourglass/stiffness.hpp) and IHQ 6 (hourglass/assumed_strain.hpp); empty for the viscous forms.
#pragma once

#include <vector>

#include "hourglass/assumed_strain.hpp"
#include "hourglass/stiffness.hpp"

namespace plyimpact::solver {

// (num_elements) for IHQ 4/5, (num_elements, 6) for IHQ 6, empty otherwise (ELFORM 1 only; rigid
// parts have no element pass).
inline std::vector<double> hourglass_moduli(const model::Model& model, const model::ElementBlock& block) {
  if (block.elform != 1 || model.materials[block.material].kind == model::MaterialKind::Rigid) return {};
  if (block.ihq == 4 || block.ihq == 5) return hourglass::stiffness_hourglass_moduli(model, block);
  if (block.ihq == 6) return hourglass::assumed_strain_moduli(model, block);
  return {};
}

}  // namespace plyimpact::solver
