// Erosion neighbourhoods of *MAT_054 elements with erosion_nonlocal (docs/theory.md, "Erosion
// strains and the element length"): for each element shorter than its reference length, the
// elements of its block whose centres lie within that length of its centre, with bell weights.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace plyimpact::model {

struct ElementBlock;

struct ErosionNeighbours {
  std::vector<Index> start;         // (num_elements + 1); empty: no element of the block has one
  std::vector<Index> index;         // neighbours, ascending per element
  std::vector<double> weight;       // w_j / W (see below)
  std::vector<double> self_weight;  // (num_elements) V_e / W; 1 for an element without neighbours
  bool empty() const { return start.empty(); }
  // Mean number of neighbours of the elements that have any.
  double mean_count() const;
  std::size_t elements_with_neighbours() const;
};

// Bell weight of a neighbour at distance r from the centre, (1 - r^2/R^2)^2 for r < R, else 0 (also
// at R to round-off, 1e-9)
// [BJ02 in docs/theory.md]: smooth, and a straight band of width h << R through the centre carries the share
// 16 h / (5 pi R) of the total (1.02 h / R), so a one-element band erodes at about the strains the
// scaling by R / h would give, and a uniform field at the card's.
double bell_weight(double r, double radius);

// Neighbourhoods of radius `radius` for the elements with needs[e]: the block's elements j != e
// whose centroids (reference coordinates X) lie closer than radius, weighted w_j = bell(r) V_j, and
// the element itself with V_e; W is the sum. Elements without needs[e] get none (their own strain).
ErosionNeighbours build_erosion_neighbours(const ElementBlock& block, const std::vector<double>& X, double radius,
                                           const std::vector<bool>& needs);

}  // namespace plyimpact::model
