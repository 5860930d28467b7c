// Builds the output frames from the solver's current state: one of the deformable bodies, one of
// the rigid bodies (FrameWriter writes them as the two named blocks of each time of the .pvd).
//
// Bodies: the deformable parts' hexahedra over the nodes they use (nodes of no element, such as
// the unused copies of bonded interface nodes, are left out; the point field node_id keeps each
// point's model node number). Strains are computed here, at output time only, from the
// deformation gradient at the element centre: logarithmic (Hencky) strain 1/2 ln(F F^T) in current
// global axes, tensor (not engineering) shear components. Material-axis fields use the current
// axes: *MAT_054's own (rotated with the element's spin), R a0 for *MAT_002 with R from the polar
// decomposition F = R U; for isotropic parts the global axes. With penalty contacts the point field
// contact_force holds each node's contact force of the last cycle (N).
//
// Rigid: the meshed rigid impactor's surface (quadrilaterals) and the hexahedra of *MAT_020 parts,
// at their current positions, so the impactor moves in ParaView.
//
// Both carry field data: units per array, legends of coded arrays (part names, erosion causes,
// failure flags) and notes (frame_legends.hpp).
#pragma once

#include "output/frame.hpp"
#include "solver/solver.hpp"

namespace plyimpact::run {

output::Frame make_frame(const solver::Solver& solver);

// No cells (and no points) when the model has no rigid body with geometry.
output::Frame make_rigid_frame(const solver::Solver& solver);

}  // namespace plyimpact::run
