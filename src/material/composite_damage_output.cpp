// Output fields of *MAT_054/055. See composite_damage_output.hpp.
#include "material/composite_damage_output.hpp"

#include "material/composite_damage.hpp"

namespace plyimpact::material {
namespace {

namespace H = composite_history;

// History slot of each output, same order as the names.
constexpr std::array<int, kCompositeDamageOutputs> kSlots = {
    H::kFibreTension, H::kFibreCompression, H::kMatrixTension, H::kMatrixCompression,
    H::kCriteria + 0, H::kCriteria + 1,    H::kCriteria + 2,  H::kCriteria + 3,
    H::kXT,           H::kXC,              H::kTransverseShearDamage, H::kCrashfront,
    H::kCause};

}  // namespace

const std::array<const char*, kCompositeDamageOutputs>& composite_damage_output_names() {
  static constexpr std::array<const char*, kCompositeDamageOutputs> kNames = {
      "mat054_ef",          "mat054_ec",          "mat054_em",
      "mat054_ed",          "mat054_crit_fibre_tension",  "mat054_crit_fibre_compression",
      "mat054_crit_matrix_tension", "mat054_crit_matrix_compression", "mat054_XT",
      "mat054_XC",          "mat054_transverse_shear_damage", "mat054_crashfront",
      "mat054_erosion_cause"};
  return kNames;
}

void composite_damage_output_values(const double* history, double out[kCompositeDamageOutputs]) {
  for (int i = 0; i < kCompositeDamageOutputs; ++i) out[i] = history[kSlots[i]];
}

}  // namespace plyimpact::material
