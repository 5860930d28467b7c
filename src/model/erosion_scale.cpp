#include "model/erosion_scale.hpp"

#include <algorithm>
#include <cmath>

namespace plyimpact::model {

double ply_plane_length(const double (&x)[3][8], double volume, const Mat3& axes) {
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k < 8; ++k) {
    const double c = axes[6] * x[0][k] + axes[7] * x[1][k] + axes[8] * x[2][k];
    lo = std::min(lo, c);
    hi = std::max(hi, c);
  }
  return std::sqrt(volume / (hi - lo));
}

}  // namespace plyimpact::model
