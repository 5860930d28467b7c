// *MAT_015 / *MAT_098 update of the element pass: the Johnson-Cook return of johnson_cook.hpp point
// by point (it iterates and branches, so it does not vectorise). History: kJohnsonCookHistory
// values per integration point.
#pragma once

#include <cstddef>

#include "element/kinematics.hpp"
#include "material/johnson_cook.hpp"
#include "material/lane_point.hpp"

namespace plyimpact::material {

class JohnsonCookLanes {
 public:
  static constexpr bool kTotalLagrangian = false;
  static constexpr bool kElementRotation = false;
  static constexpr bool kIncremental = true;
  // history: (elements * points, kJohnsonCookHistory); erosion_code: reported when a point fails.
  JohnsonCookLanes(const JohnsonCookParams& p, double* history, int erosion_code)
      : p_(p), history_(history), code_(erosion_code) {}

  PLYIMPACT_LANE_KERNEL void update(const LanePoint& p, const LaneVec<6>& s_old, LaneVec<6>& s, int (&erode)[kLanes]) const {
    for (int l = 0; l < kLanes; ++l) {
      for (int i = 0; i < 6; ++i) s[i][l] = 0;
      if (l >= p.n || !p.ok[l]) continue;
      double Rl[9], Dl[6], sl[6];
      for (int i = 0; i < 9; ++i) Rl[i] = p.R[i][l];
      for (int i = 0; i < 6; ++i) Dl[i] = p.D[i][l], sl[i] = s_old[i][l];
      const auto res =
          johnson_cook_update(p_, Rl, Dl, p.dt, sl, &history_[std::size_t(p.elem[l]) * kJohnsonCookHistory]);
      for (int i = 0; i < 6; ++i) s[i][l] = sl[i];
      if (res.failed) erode[l] = code_;
    }
  }

  int update_point(const Point& p, double s[6], double* history) const {
    double R[9];
    element::hughes_winget(p.W, p.dt, R);
    return johnson_cook_update(p_, R, p.D, p.dt, s, history).failed ? code_ : 0;
  }

  void commit(Index, int) const {}

 private:
  const JohnsonCookParams& p_;
  double* history_;
  int code_;
};

}  // namespace plyimpact::material
