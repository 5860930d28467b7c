// *MAT_001 update of the element pass: hypoelastic, objective through the Hughes-Winget rotation
// sigma* = R sigma R^T, then + lambda tr(D dt) I + 2 mu D dt.
#pragma once

#include "core/voigt.hpp"
#include "element/kinematics.hpp"
#include "material/elastic.hpp"
#include "material/lane_point.hpp"

namespace plyimpact::material {

class IsotropicElasticLanes {
 public:
  static constexpr bool kTotalLagrangian = false;
  static constexpr bool kElementRotation = false;
  static constexpr bool kIncremental = true;  // reads LanePoint::R
  explicit IsotropicElasticLanes(const IsotropicConstants& c) : lambda_(c.lambda), mu_(c.mu) {}

  PLYIMPACT_LANE_KERNEL void update(const LanePoint& p, const LaneVec<6>& s_old, LaneVec<6>& s, int (&erode)[kLanes]) const {
    (void)erode;
    const double lambda = lambda_, mu = mu_, dt = p.dt;
    const LaneVec<9>& R = p.R;
    const LaneVec<6>& D = p.D;
    PLYIMPACT_LANES {
      const double S0[9] = {s_old[0][l], s_old[3][l], s_old[5][l], s_old[3][l], s_old[1][l],
                            s_old[4][l], s_old[5][l], s_old[4][l], s_old[2][l]};
      double T[9];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          T[3 * i + j] = R[3 * i][l] * S0[j] + R[3 * i + 1][l] * S0[3 + j] + R[3 * i + 2][l] * S0[6 + j];
      auto rsr = [&](int i, int j) {
        return T[3 * i] * R[3 * j][l] + T[3 * i + 1] * R[3 * j + 1][l] + T[3 * i + 2] * R[3 * j + 2][l];
      };
      const double tr = p.trD[l] * dt;
      s[0][l] = rsr(0, 0) + lambda * tr + 2 * mu * D[0][l] * dt;
      s[1][l] = rsr(1, 1) + lambda * tr + 2 * mu * D[1][l] * dt;
      s[2][l] = rsr(2, 2) + lambda * tr + 2 * mu * D[2][l] * dt;
      s[3][l] = rsr(0, 1) + 2 * mu * D[3][l] * dt;
      s[4][l] = rsr(1, 2) + 2 * mu * D[4][l] * dt;
      s[5][l] = rsr(2, 0) + 2 * mu * D[5][l] * dt;
    }
  }

  int update_point(const Point& p, double s[6], double* history) const {
    (void)history;
    double R[9];
    element::hughes_winget(p.W, p.dt, R);
    rotate_voigt(R, s, s);
    const double* D = p.D;
    const double dt = p.dt, lambda = lambda_, mu = mu_;
    const double tr = (D[0] + D[1] + D[2]) * dt;
    s[0] += lambda * tr + 2 * mu * D[0] * dt;
    s[1] += lambda * tr + 2 * mu * D[1] * dt;
    s[2] += lambda * tr + 2 * mu * D[2] * dt;
    s[3] += 2 * mu * D[3] * dt;
    s[4] += 2 * mu * D[4] * dt;
    s[5] += 2 * mu * D[5] * dt;
    return 0;
  }

  void commit(Index, int) const {}

 private:
  double lambda_, mu_;
};

}  // namespace plyimpact::material
