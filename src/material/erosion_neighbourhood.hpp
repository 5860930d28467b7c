// The neighbourhood over which a *MAT_054 element's erosion strains are averaged (erosion_nonlocal,
// docs/theory.md "Erosion strains and the element length"): besides its scaled limits, an element
// erodes by a card's limit when both its own strain and the weighted mean over the elements within
// erosion_reference_length of it pass it. Raw views of model::ErosionNeighbours and the run state's
// strain buffers.
#pragma once

#include <cstddef>

#include "core/types.hpp"

namespace plyimpact::material {

struct ErosionNeighbourhoodView {
  const Index* start = nullptr;         // (elements + 1) into index / weight
  const Index* index = nullptr;         // neighbours (element indices of the block)
  const double* weight = nullptr;       // their weights, normalised with the element's own
  const double* self_weight = nullptr;  // (elements) the element's own weight
  const double* read = nullptr;         // (elements, 6) element-mean strains of the previous pass
  double* write = nullptr;              // (elements, 6) this pass's

  bool has(Index e) const { return start != nullptr && start[e + 1] > start[e]; }

  // Mean of the strain (material axes, engineering shear) over element e's neighbourhood, with the
  // element's own current strain `own` and its neighbours' strains of the previous pass (read-only
  // in this pass, so the result does not depend on the order or the thread the elements run on).
  void mean(Index e, const double own[6], double out[6]) const {
    const double w0 = self_weight[e];
    for (int i = 0; i < 6; ++i) out[i] = w0 * own[i];
    for (Index k = start[e]; k < start[e + 1]; ++k) {
      const double w = weight[k];
      const double* s = read + 6 * std::size_t(index[k]);
      for (int i = 0; i < 6; ++i) out[i] += w * s[i];
    }
  }
};

}  // namespace plyimpact::material
