#include "solver/erosion.hpp"

#include "material/composite_damage.hpp"

namespace plyimpact::solver {

bool can_erode(const model::Model& model) {
  if (model.control.erode_tsmin > 0) return true;
  for (const auto& m : model.materials)
    if (m.can_fail()) return true;
  return false;
}

const char* erosion_cause_name(int cause) {
  if (cause == int(ErosionCause::PlasticStrain)) return "plastic_strain";
  if (cause == int(ErosionCause::TimeStep)) return "time_step";
  if (cause > int(ErosionCause::CompositeBase))
    return material::composite_damage_cause_name(
        material::CompositeDamageCause(cause - int(ErosionCause::CompositeBase)));
  return "unknown";
}

}  // namespace plyimpact::solver
