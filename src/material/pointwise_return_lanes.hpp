// Lane adapter of the element pass for materials whose stress return iterates and branches point by
// point (J2 plasticity, Johnson-Cook): such returns do not vectorise, so each lane is handed to the
// scalar update with its own rotation and history. Update(params, R, D, dt, stress, history) returns
// a result with a `failed` flag; kHistory is the number of history values per integration point.
#pragma once

#include <cstddef>

#include "element/kinematics.hpp"
#include "material/lane_point.hpp"

namespace plyimpact::material {

template <class Params, auto Update, int kHistory>
class PointwiseReturnLanes {
 public:
  static constexpr bool kTotalLagrangian = false;
  static constexpr bool kElementRotation = false;
  static constexpr bool kIncremental = true;
  // history: (elements * points, kHistory); erosion_code: reported when a point fails.
  PointwiseReturnLanes(const Params& p, double* history, int erosion_code)
      : p_(p), history_(history), code_(erosion_code) {}

  PLYIMPACT_LANE_KERNEL void update(const LanePoint& p, const LaneVec<6>& s_old, LaneVec<6>& s, int (&erode)[kLanes]) const {
    for (int l = 0; l < kLanes; ++l) {
      for (int i = 0; i < 6; ++i) s[i][l] = 0;
      if (l >= p.n || !p.ok[l]) continue;
      double Rl[9], Dl[6], sl[6];
      for (int i = 0; i < 9; ++i) Rl[i] = p.R[i][l];
      for (int i = 0; i < 6; ++i) Dl[i] = p.D[i][l], sl[i] = s_old[i][l];
      const auto res = Update(p_, Rl, Dl, p.dt, sl, &history_[std::size_t(p.elem[l]) * kHistory]);
      for (int i = 0; i < 6; ++i) s[i][l] = sl[i];
      if (res.failed) erode[l] = code_;
    }
  }

  int update_point(const Point& p, double s[6], double* history) const {
    double R[9];
    element::hughes_winget(p.W, p.dt, R);
    return Update(p_, R, p.D, p.dt, s, history).failed ? code_ : 0;
  }

  void commit(Index, int) const {}

 private:
  const Params& p_;
  double* history_;
  int code_;
};

}  // namespace plyimpact::material
