// Basic scalar, index and small fixed-size vector types used across plyimpact.
// Internally every quantity is SI (m, kg, s, N, Pa, J); unit conversion happens only in config/.
#pragma once

#include <array>
#include <cstdint>

namespace plyimpact {

using Real = double;
using Index = std::int32_t;  // node / element index inside one run (0-based)
using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major 3x3

}  // namespace plyimpact
