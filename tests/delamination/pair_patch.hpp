// A 3 x 3 patch of interface pairs for the tiebreak kernel's tests: pair p = 3 j + i has lower node
// p and upper node 9 + p, both at i a e_x + j a e_y (the plies coincide), and the patch's four faces
// are quads of pair indices, counter-clockwise seen from the upper ply when e_x x e_y is the normal.
#pragma once

#include <array>
#include <vector>

#include "cohesive/tiebreak_pairs.hpp"

namespace plyimpact::cohesive::test {

struct PairPatch {
  TiebreakPairsSpec spec;
  std::vector<double> x;  // (18, 3) node coordinates
};

inline PairPatch pair_patch_3x3(double a, std::array<double, 3> ey = {0, 1, 0}) {
  PairPatch patch;
  patch.x.assign(2 * 9 * 3, 0.0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int p = 3 * j + i;
      patch.spec.lower.push_back(p);
      patch.spec.upper.push_back(9 + p);
      for (int k = 0; k < 3; ++k)
        patch.x[3 * p + k] = patch.x[3 * (9 + p) + k] = (k == 0 ? i * a : 0) + j * a * ey[std::size_t(k)];
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const Index q = 3 * j + i;
      patch.spec.faces.insert(patch.spec.faces.end(), {q, q + 1, q + 4, q + 3});
    }
  return patch;
}

}  // namespace plyimpact::cohesive::test
