// Builds an output frame (points, hexahedra, fields) from the solver's current state. Strains are
// computed here, at output time only, from the deformation gradient at the element centre:
// logarithmic (Hencky) strain 1/2 ln(F F^T) in current global axes, tensor (not engineering) shear
// components. Material-axis fields use the current axes R a0, with R from the polar decomposition
// F = R U; for isotropic parts the material axes are the global axes. With penalty contacts the
// point field contact_force holds each node's contact force of the last cycle (N).
#pragma once

#include "output/frame.hpp"
#include "solver/solver.hpp"

namespace plyimpact::run {

output::Frame make_frame(const solver::Solver& solver);

}  // namespace plyimpact::run
