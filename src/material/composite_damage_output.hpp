// Per-point output of *MAT_054/055 for ParaView: names and values read from the history
// (material/composite_damage.hpp). Mode flags follow LS-DYNA (1 intact, 0 failed).
#pragma once

#include <array>

namespace plyimpact::material {

inline constexpr int kCompositeDamageOutputs = 13;

// Stable field names, in the order of composite_damage_output_values.
const std::array<const char*, kCompositeDamageOutputs>& composite_damage_output_names();

// history: kCompositeDamageHistory doubles of one point. Values: mode flags e_f e_c e_m e_d, the four
// last criterion values (e^2, >= 0 failed), current XT and XC (Pa), transverse shear damage,
// crashfront flag, erosion cause (CompositeDamageCause as a number, 0 = alive).
void composite_damage_output_values(const double* history, double out[kCompositeDamageOutputs]);

}  // namespace plyimpact::material
