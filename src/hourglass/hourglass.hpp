// Hourglass control of the one-point hexahedron: which IHQ uses what, and the nodal forces of the
// generalised hourglass forces. The force laws: viscous.hpp (IHQ 1-3), stiffness.hpp (IHQ 4-5),
// assumed_strain.hpp (IHQ 6). Hourglass base and shape vectors: element/hex8.hpp, hex8_lanes.hpp.
#pragma once

#include "core/lanes.hpp"

namespace plyimpact::hourglass {

template <int IHQ>
struct Traits {
  static constexpr bool kProject = IHQ != 1;                  // gamma projected (IHQ 2-6), or bare Gamma (IHQ 1)
  static constexpr bool kExactGradient = IHQ == 3 || IHQ == 5;  // Flanagan-Belytschko mean gradient and volume
  static constexpr bool kStiffness = IHQ == 4 || IHQ == 5;    // accumulated, rotated with R
  static constexpr bool kAssumedStrain = IHQ == 6;            // accumulated in the element frame
  static constexpr bool kViscous = !kStiffness && !kAssumedStrain;
};

// Nodal forces f_ik -= sum_a Q_ia gamma_ak.
PLYIMPACT_LANE_KERNEL void add_hourglass_forces_lanes(const double (&Qh)[3][4][kLanes], const double (&gamma)[4][8][kLanes],
                                       double (&fe)[3][8][kLanes]) {
  PLYIMPACT_LANES {
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k)
        fe[i][k][l] -= Qh[i][0][l] * gamma[0][k][l] + Qh[i][1][l] * gamma[1][k][l] + Qh[i][2][l] * gamma[2][k][l] +
                       Qh[i][3][l] * gamma[3][k][l];
  }
}

}  // namespace plyimpact::hourglass
