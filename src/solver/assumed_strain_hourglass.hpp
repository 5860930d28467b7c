// The IHQ 6 moduli live in hourglass/assumed_strain.hpp; this name keeps solver.cpp's include
// working until it includes that header itself.
#pragma once

#include "hourglass/assumed_strain.hpp"

namespace plyimpact::solver {
using hourglass::assumed_strain_moduli;
}  // namespace plyimpact::solver
