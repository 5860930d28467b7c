// Material axes as on LS-DYNA orthotropic cards (shared by *MAT_002 and *MAT_054 specs).
#pragma once

#include "core/types.hpp"

namespace plyimpact::config {

// Material axes as on LS-DYNA orthotropic cards (AOPT 0, 2, 3) plus the element/part angle BETA.
struct MaterialAxes {
  int AOPT = 0;                  // 0: element nodes 1-2-4; 2: global vectors A, D; 3: V x mid-surface normal
  Vec3 A{1, 0, 0};               // AOPT 2
  Vec3 D{0, 1, 0};               // AOPT 2
  Vec3 V{1, 0, 0};               // AOPT 3
  double BETA = 0;               // rad, rotation of a and b about c (MANGLE / BETA on the card)
};

}  // namespace plyimpact::config
