// Element pass: for a range of one block's elements, from the current coordinates x^{n+1} and
// velocities v^{n+1/2}, update the stresses to t^{n+1}, add the internal, bulk-viscous and
// hourglass forces to the nodal force array, accumulate element energies and find the element
// stable time step. The element family of the block (element_families.hpp) does the work; one
// template instance per (family, material, hourglass) combination, chosen once per chunk.
#pragma once

#include <limits>
#include <utility>
#include <vector>

#include "model/model.hpp"
#include "solver/erosion.hpp"
#include "solver/state.hpp"

namespace plyimpact::solver {

struct ChunkResult {
  double internal_energy = 0;     // J added in this pass
  double hourglass_energy = 0;
  double bulk_viscous_energy = 0;
  double dt_min = std::numeric_limits<double>::infinity();  // smallest element step (no TSSFAC)
  Index dt_element = -1;          // its element id
  Index bad_element = -1;         // first element with a non-positive volume or non-finite result
  double bad_volume = 0;
  bool bad_is_nan = false;
  // Elements whose material failed in this pass (to be deleted by the solver), in element order,
  // with their erosion cause (ErosionCause), and the internal + hourglass energy they held.
  std::vector<ErodedElement> eroded;
  double eroded_energy = 0;
  double eroded_hourglass_energy = 0;  // J, the hourglass part of eroded_energy
};


// dt: Delta t^{n+1/2} (0 for the initial evaluation, which changes no stress).
void update_elements(const model::Model& model, const model::ElementBlock& block, BlockState& state, Index begin,
                     Index end, const double* x, const double* v, double* f, double dt, ChunkResult& result);

// The state of block b at t = 0: zero stress, forces and energies, the materials' initial history
// and axes, the reference volumes.
BlockState initial_block_state(const model::Model& model, std::size_t b);

// Each element's stable step (no TSSFAC) at the reference geometry, at rest, as the element family
// computes it (including the block's step_scale, if set), by one element pass at dt = 0 on a
// scratch state. For mass scaling (solver/mass_scaling), so that the step has one definition.
std::vector<double> initial_element_steps(const model::Model& model, std::size_t b);

}  // namespace plyimpact::solver
