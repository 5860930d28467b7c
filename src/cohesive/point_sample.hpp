// What an output frame shows of one point of an interface law (damage, mixity, opening, traction),
// and the helper that evaluates it from the point's history without changing that history: the
// common tail of the kernels' sample() (tiebreak pairs, segment ties, cohesive elements).
#pragma once

#include "cohesive/traction_law.hpp"

namespace plyimpact::cohesive {

struct PairSample {
  double damage = 0;
  double mixity = 0;                // G_II / G_T
  double opening[3] = {0, 0, 0};    // m, (normal, shear 1, shear 2)
  double traction[3] = {0, 0, 0};   // Pa, same frame
};

// s.opening holds the point's opening; fills damage, mixity and traction as one traction_update from
// the history h (taken by value: the caller's history is not changed).
inline void sample_point(const TractionLaw& law, PointHistory h, PairSample& s) {
  PointResponse r;
  traction_update(law, s.opening, h, r);
  s.damage = r.damage;
  s.mixity = r.mixity;
  for (int i = 0; i < 3; ++i) s.traction[i] = r.traction[i];
}

}  // namespace plyimpact::cohesive
