// Imposed opening paths for single-point tests of the traction laws: the law is driven along a
// path and the test integrates the tractions it returns, so the energies it checks are the work the
// law's own tractions do, independent of how the law computes its dissipation.
#pragma once

#include <cmath>
#include <vector>

#include "cohesive/traction_law.hpp"

namespace plyimpact::cohesive::test {

// Seed Table 8.6 (T800S/M21, OPTION 9 column) in SI: NFLS = SFLS = 60 MPa, ERATEN 765 J/m^2,
// ERATES 1250 J/m^2, CN = 100 kN/mm^3 = 1e14 Pa/m, CT2CN 1, PARAM (alpha) 1.
inline TractionLawParams table_8_6_option9() {
  TractionLawParams p;
  p.option = TiebreakOption::MixedMode;
  p.NFLS = 60e6;
  p.SFLS = 60e6;
  p.PARAM = 1;
  p.ERATEN = 765;
  p.ERATES = 1250;
  p.CN = 1e14;
  p.CT2CN = 1;
  return p;
}

struct PathPoint {
  double u[3] = {0, 0, 0};  // opening (normal, shear 1, shear 2), m
  PointResponse r;      // the law's answer
};

// Work of the law's tractions along the recorded path, split by mode (trapezoid rule per step:
// exact where the traction is linear in the opening within the step).
struct PathWork {
  double normal = 0;  // J/m^2, integral of t_n d delta_n
  double shear = 0;   // J/m^2, integral of t_s . d delta_s
  double dissipated = 0;  // J/m^2, sum of the law's dissipated increments
};

inline PathWork work_along(const std::vector<PathPoint>& path) {
  PathWork w;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const auto& a = path[i - 1];
    const auto& b = path[i];
    w.normal += 0.5 * (a.r.traction[0] + b.r.traction[0]) * (b.u[0] - a.u[0]);
    for (int k = 1; k < 3; ++k) w.shear += 0.5 * (a.r.traction[k] + b.r.traction[k]) * (b.u[k] - a.u[k]);
  }
  for (const auto& p : path) w.dissipated += p.r.dissipated_increment;
  return w;
}

// Drives the law from the current history along the straight segment from `from` to `to` in
// `steps` equal steps, appending each point (the start point is not repeated).
inline void drive(const TractionLaw& law, PointHistory& h, const double from[3], const double to[3], int steps,
                  std::vector<PathPoint>& path) {
  const double a[3] = {from[0], from[1], from[2]};  // `from` may point into `path`, which grows
  const double b[3] = {to[0], to[1], to[2]};
  for (int i = 1; i <= steps; ++i) {
    PathPoint p;
    const double s = double(i) / steps;
    for (int k = 0; k < 3; ++k) p.u[k] = a[k] + s * (b[k] - a[k]);
    traction_update(law, p.u, h, p.r);
    path.push_back(p);
  }
}

// A ray from the origin: opening direction (normal, shear 1, shear 2) scaled to `magnitude`.
inline std::vector<PathPoint> ray(const TractionLaw& law, PointHistory& h, const double dir[3], double magnitude,
                                  int steps) {
  std::vector<PathPoint> path(1);
  for (int k = 0; k < 3; ++k) path[0].u[k] = 0;
  traction_update(law, path[0].u, h, path[0].r);
  const double to[3] = {dir[0] * magnitude, dir[1] * magnitude, dir[2] * magnitude};
  drive(law, h, path[0].u, to, steps, path);
  return path;
}

inline double norm3(const double a[3]) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

}  // namespace plyimpact::cohesive::test
