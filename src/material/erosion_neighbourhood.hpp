// The neighbourhood over which a *MAT_054 element's erosion strains are averaged (erosion_nonlocal,
// docs/theory.md "Erosion strains and the element length"): besides its scaled limits, an element
// erodes by a card's limit when the weighted mean strain over the elements within
// erosion_reference_length of it (itself included) reaches it, as *MAT_NONLOCAL averages a failure
// variable. Raw views of model::ErosionNeighbours and the run state's strain buffers.
#pragma once

#include <cstddef>

#include "core/types.hpp"

namespace plyimpact::material {

// Values per element in the strain buffers: the element-mean strain in material axes (engineering
// shear), then 1 if that strain passed one of the card's limits, else 0.
inline constexpr int kErosionStrainStride = 7;
inline constexpr int kErosionStrainPastCard = 6;

struct ErosionNeighbourhoodView {
  const Index* start = nullptr;         // (elements + 1) into index / weight
  const Index* index = nullptr;         // neighbours (element indices of the block)
  const double* weight = nullptr;       // their weights, normalised with the element's own
  const double* self_weight = nullptr;  // (elements) the element's own weight
  const double* read = nullptr;         // (elements, kErosionStrainStride) of the previous pass
  double* write = nullptr;              // (elements, kErosionStrainStride) this pass's

  bool has(Index e) const { return start != nullptr && start[e + 1] > start[e]; }

  // Whether element e or a neighbour passed a card limit in the previous pass. The mean of the
  // neighbourhood can reach a limit only then: the weights are positive and sum to one, and each
  // limit bounds a component, its magnitude or a norm, all of which a weighted mean cannot exceed.
  bool any_past_card(Index e) const {
    bool past = read[kErosionStrainStride * std::size_t(e) + kErosionStrainPastCard] != 0;
    for (Index k = start[e]; k < start[e + 1] && !past; ++k)
      past = read[kErosionStrainStride * std::size_t(index[k]) + kErosionStrainPastCard] != 0;
    return past;
  }

  // Mean strain over element e's neighbourhood in the previous pass, its own included. Every term
  // is read-only in this pass, so the result depends neither on the order nor on the thread the
  // elements run on. An eroded neighbour counts with its strain when it eroded.
  void mean(Index e, double out[6]) const {
    const double w0 = self_weight[e];
    const double* own = read + kErosionStrainStride * std::size_t(e);
    for (int i = 0; i < 6; ++i) out[i] = w0 * own[i];
    for (Index k = start[e]; k < start[e + 1]; ++k) {
      const double w = weight[k];
      const double* s = read + kErosionStrainStride * std::size_t(index[k]);
      for (int i = 0; i < 6; ++i) out[i] += w * s[i];
    }
  }
};

}  // namespace plyimpact::material
