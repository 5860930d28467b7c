// Cell fields of the material state for the output frame: `alive` (0 once an element is eroded;
// apply ParaView's Threshold on it to hide eroded elements), `plastic_strain` (*MAT_003/024/015/098),
// `temperature` (K, *MAT_015 with adiabatic heating; NaN in other materials) and
// the *MAT_054 damage fields (mode flags, criterion values, reduced strengths, erosion cause).
// Cells of other materials get 0 plastic strain and NaN damage fields (shown as "no value").
#pragma once

#include "output/frame.hpp"
#include "solver/solver.hpp"

namespace plyimpact::run {

// Appends the fields; cells are in the frame's order (blocks in order, elements in block order).
void add_material_fields(const solver::Solver& solver, output::Frame& frame);

}  // namespace plyimpact::run
