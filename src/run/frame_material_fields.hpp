// Cell fields of the material state for the output frame: `alive` (0 once an element is eroded;
// apply ParaView's Threshold on it to hide eroded elements), `plastic_strain` (*MAT_003/024/015/098),
// `temperature` (K, *MAT_015 with adiabatic heating; NaN in other materials) and
// the *MAT_054 damage fields (mode flags, criterion values, reduced strengths, erosion cause).
// Cells of other materials get 0 plastic strain and NaN damage fields: NaN rather than a number
// because 0 is a meaningful damage value (a failed mode), NaN is ParaView's "no value" (its NaN
// colour) and Threshold leaves NaN cells out; a field-data note in the file says so. Also adds the
// legends of the coded fields (legend_alive, legend_mat054_*) as field data.
#pragma once

#include "output/frame.hpp"
#include "solver/solver.hpp"

namespace plyimpact::run {

// Appends the fields; cells are in the bodies frame's order (its blocks in order, elements in
// block order; rigid blocks are not in it).
void add_material_fields(const solver::Solver& solver, output::Frame& frame);

}  // namespace plyimpact::run
