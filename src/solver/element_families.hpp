// Element families of the element pass. Each family is one file with one entry point over a chunk
// of a block: gather -> element kinematics (element/) -> material update (material/, chosen by
// with_material) -> hourglass (hourglass/) -> forces, energies, step, erosion (erosion.hpp) ->
// scatter. update_elements (element_update.cpp) picks the family of the block.
//
// The next family, the zero-thickness 8-node cohesive element of *MAT_138 (LS-DYNA ELFORM 19/20),
// slots in here: an ElementFamily value, a case in element_family, and update_cohesive8 in its own
// file. It keeps the same contract as the hexahedra (gather, scatter in element order, ChunkResult
// with energies, dt_min, bad elements and eroded elements through erosion.hpp) but integrates
// tractions over its mid-surface from the separation of its two faces, so its "material" is a
// traction-separation law with its own registry (separation in, traction and damage out), not
// with_material's stress update; its history sits in BlockState::history like a material's.
#pragma once

#include "model/model.hpp"
#include "solver/element_update.hpp"
#include "solver/state.hpp"

namespace plyimpact::solver {

enum class ElementFamily {
  Hex8OnePoint,          // ELFORM 1: one point + hourglass control (element_hex8_one_point.cpp)
  Hex8SelectiveReduced,  // ELFORM 2 / -2: 2x2x2 points, B-bar (element_hex8_selective.cpp)
};

inline ElementFamily element_family(const model::ElementBlock& block) {
  return block.fully_integrated() ? ElementFamily::Hex8SelectiveReduced : ElementFamily::Hex8OnePoint;
}

void update_hex8_one_point(const model::Model& model, const model::ElementBlock& block, BlockState& state,
                           Index begin, Index end, const double* x, const double* v, double* f, double dt,
                           ChunkResult& result);
void update_hex8_selective(const model::Model& model, const model::ElementBlock& block, BlockState& state,
                           Index begin, Index end, const double* x, const double* v, double* f, double dt,
                           ChunkResult& result);

}  // namespace plyimpact::solver
