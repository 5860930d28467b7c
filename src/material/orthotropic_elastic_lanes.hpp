// *MAT_002 update of the element pass: total Lagrangian, F = J_x J_X^-1 (one point: the stored
// inverse reference centre Jacobian) or the family's F-bar, Green-Lagrange E = (F^T F - I)/2
// (engineering Voigt), S = C E with the stiffness in global reference axes, sigma = F S F^T / det F.
// Objective and exact for any rotation.
#pragma once

#include <cstddef>

#include "material/elastic.hpp"
#include "material/lane_point.hpp"

namespace plyimpact::material {

// Total-Lagrangian stress of one point from F (row-major), its determinant J and C (6x6 row-major);
// dE, if given, is added to the Green-Lagrange strain of F (engineering Voigt).
inline void total_lagrangian_stress(const double F[9], double J, const double* C, double s[6],
                                    const double* dE = nullptr) {
  double E[6];  // engineering Voigt Green-Lagrange strain
  auto ftf = [&](int i, int j) { return F[i] * F[j] + F[3 + i] * F[3 + j] + F[6 + i] * F[6 + j]; };
  E[0] = 0.5 * (ftf(0, 0) - 1);
  E[1] = 0.5 * (ftf(1, 1) - 1);
  E[2] = 0.5 * (ftf(2, 2) - 1);
  E[3] = ftf(0, 1);
  E[4] = ftf(1, 2);
  E[5] = ftf(2, 0);
  if (dE)
    for (int i = 0; i < 6; ++i) E[i] += dE[i];
  double Sv[6];
  for (int r = 0; r < 6; ++r)
    Sv[r] = C[6 * r] * E[0] + C[6 * r + 1] * E[1] + C[6 * r + 2] * E[2] + C[6 * r + 3] * E[3] + C[6 * r + 4] * E[4] +
            C[6 * r + 5] * E[5];
  const double S[9] = {Sv[0], Sv[3], Sv[5], Sv[3], Sv[1], Sv[4], Sv[5], Sv[4], Sv[2]};
  double T[9];  // F S
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[3 * i + j] = F[3 * i] * S[j] + F[3 * i + 1] * S[3 + j] + F[3 * i + 2] * S[6 + j];
  const double rJ = 1.0 / J;
  auto fsf = [&](int i, int j) { return (T[3 * i] * F[3 * j] + T[3 * i + 1] * F[3 * j + 1] + T[3 * i + 2] * F[3 * j + 2]) * rJ; };
  s[0] = fsf(0, 0);
  s[1] = fsf(1, 1);
  s[2] = fsf(2, 2);
  s[3] = fsf(0, 1);
  s[4] = fsf(1, 2);
  s[5] = fsf(2, 0);
}

// The same for lane l, F = J_x J_X^-1 and J = det F. `stiffness(i)` returns entry i of the 6x6
// global stiffness of that lane.
template <class Stiffness>
PLYIMPACT_LANE_KERNEL void total_lagrangian_lane(const LaneVec<9>& Jx, const LaneVec<9>& Ji, int l, Stiffness stiffness,
                                  LaneVec<6>& s) {
  double F[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      F[3 * i + j] = Jx[3 * i][l] * Ji[j][l] + Jx[3 * i + 1][l] * Ji[3 + j][l] + Jx[3 * i + 2][l] * Ji[6 + j][l];
  const double J =
      F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
  auto ftf = [&](int i, int j) { return F[i] * F[j] + F[3 + i] * F[3 + j] + F[6 + i] * F[6 + j]; };
  const double E[6] = {0.5 * (ftf(0, 0) - 1), 0.5 * (ftf(1, 1) - 1), 0.5 * (ftf(2, 2) - 1),
                       ftf(0, 1),             ftf(1, 2),             ftf(2, 0)};
  double Sv[6];
  for (int a = 0; a < 6; ++a) {
    double sum = 0;
    for (int c = 0; c < 6; ++c) sum += stiffness(6 * a + c) * E[c];
    Sv[a] = sum;
  }
  const double S[9] = {Sv[0], Sv[3], Sv[5], Sv[3], Sv[1], Sv[4], Sv[5], Sv[4], Sv[2]};
  double T[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[3 * i + j] = F[3 * i] * S[j] + F[3 * i + 1] * S[3 + j] + F[3 * i + 2] * S[6 + j];
  const double rJ = 1.0 / J;
  auto fsf = [&](int i, int j) { return (T[3 * i] * F[3 * j] + T[3 * i + 1] * F[3 * j + 1] + T[3 * i + 2] * F[3 * j + 2]) * rJ; };
  s[0][l] = fsf(0, 0), s[1][l] = fsf(1, 1), s[2][l] = fsf(2, 2);
  s[3][l] = fsf(0, 1), s[4][l] = fsf(1, 2), s[5][l] = fsf(2, 0);
}

class OrthotropicElasticLanes {
 public:
  static constexpr bool kTotalLagrangian = true;  // reads LanePoint::Jx, Point::F and J
  static constexpr bool kElementRotation = false;
  static constexpr bool kIncremental = false;
  // reference_jacobian_inverse: (elements, 9) J_X^-1 of the reference centre (ELFORM 1 only);
  // orientation: (elements) index into `orientations`.
  OrthotropicElasticLanes(const double* reference_jacobian_inverse, const int* orientation,
                          const Orientation* orientations)
      : ji_(reference_jacobian_inverse), orientation_(orientation), orientations_(orientations) {}

  PLYIMPACT_LANE_KERNEL void update(const LanePoint& p, const LaneVec<6>& s_old, LaneVec<6>& s, int (&erode)[kLanes]) const {
    (void)s_old, (void)erode;
    alignas(64) double Ji[9][kLanes];
    for (int l = 0; l < kLanes; ++l) {
      const double* src = &ji_[9 * std::size_t(p.elem[l])];
      for (int i = 0; i < 9; ++i) Ji[i][l] = src[i];
    }
    // A ply has one orientation almost always: then the stiffness is broadcast, not copied per lane.
    const int o0 = orientation_[p.elem[0]];
    bool uniform = true;
    for (int l = 1; l < kLanes; ++l) uniform = uniform && orientation_[p.elem[l]] == o0;
    const LaneVec<9>& Jx = p.Jx;
    if (uniform) {
      const double* C0 = orientations_[o0].c_global.data();
      PLYIMPACT_LANES total_lagrangian_lane(Jx, Ji, l, [&](int i) { return C0[i]; }, s);
    } else {
      alignas(64) double Cv[36][kLanes];
      for (int l = 0; l < kLanes; ++l) {
        const double* Cl = orientations_[orientation_[p.elem[l]]].c_global.data();
        for (int i = 0; i < 36; ++i) Cv[i][l] = Cl[i];
      }
      PLYIMPACT_LANES total_lagrangian_lane(Jx, Ji, l, [&](int i) { return Cv[i][l]; }, s);
    }
  }

  int update_point(const Point& p, double s[6], double* history) const {
    (void)history;
    total_lagrangian_stress(p.F, p.J, orientations_[orientation_[p.element]].c_global.data(), s, p.dE);
    return 0;
  }

  void commit(Index, int) const {}

 private:
  const double* ji_;
  const int* orientation_;
  const Orientation* orientations_;
};

}  // namespace plyimpact::material
