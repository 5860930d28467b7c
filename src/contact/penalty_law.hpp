// The penalty law of a node-segment pair (docs/theory.md section 10), as pure functions of the pair's
// data in the segment set (contact node i, segment s) and its kinematics: no search, no history
// beyond the friction force handed in.
//   stiffness : SOFT 0  k = min(k_node, k_seg), k_seg = SLSFAC SF K A^2 / V (PENOPT 1; segment set)
//               SOFT 1  k = max(SOFT 0 value, SOFSCL 0.5 m* / dt_c^2), m* = min(node, segment mass)
//               SOFT 2  k = 0.5 SLSFAC SF (m1 m2 / (m1 + m2)) / dt_c^2, m = segment masses
//   normal    : f_n = k |g| on a penetration g < 0, minus VDC % of the critical damping of the
//               two-mass spring on the normal relative velocity, never tensile with VDC
//   friction  : elastic-slip return map, trial f_t - k v_t dt limited to mu f_n with
//               mu = FD + (FS - FD) exp(-DC |v_t|)
// The same k enters the stable step (a spring k b b^T, penalty_contact) and the friction's elastic
// slope, so the tangential direction is never stiffer than the normal one.
// dt_c: the step of the SOFT 1/2 stiffness (DTSTIF, or the initial solution step).
#pragma once

#include <algorithm>
#include <cmath>

#include "config/scene.hpp"
#include "contact/geometry.hpp"
#include "contact/segment_set.hpp"

namespace plyimpact::contact {

struct PenaltyLaw {
  int SOFT = 0;
  double SOFSCL = 0.1, SLSFAC = 0.1, SFS = 1, SFM = 1;
  double FS = 0, FD = 0, DC = 0, VDC = 0;
  double dt_c = 0;  // s

  PenaltyLaw() = default;
  PenaltyLaw(const config::ContactSpec& spec, double dt_c_)
      : SOFT(spec.SOFT), SOFSCL(spec.SOFSCL), SLSFAC(spec.SLSFAC), SFS(spec.SFS), SFM(spec.SFM), FS(spec.FS),
        FD(spec.FD), DC(spec.DC), VDC(spec.VDC), dt_c(dt_c_) {}

  double scale(int side) const { return SLSFAC * (side == 0 ? SFS : SFM); }
  bool friction() const { return FS > 0 || FD > 0; }

  // Spring stiffness of the pair of contact node i and segment s of the set, N/m. Reads only what
  // the SOFT option needs (a hot path: each read is a likely cache miss on a large surface).
  double stiffness(const SegmentSet& set, std::size_t i, std::size_t s) const {
    if (SOFT == 2) {
      const double sf = scale(set.node_side(i));
      const double m1 = set.node_segment_mass(i), m2 = set.segment_mass(s);
      return m1 + m2 > 0 ? 0.5 * sf * m1 * m2 / (m1 + m2) / (dt_c * dt_c) : 0.0;
    }
    double k0 = std::min(set.node_stiffness(i), set.segment_stiffness(s));  // PENOPT 1
    if (!std::isfinite(k0)) k0 = 0;
    if (SOFT == 0) return k0;
    const double m = std::min(set.node_mass(i), set.segment_node_mass(s));
    return std::max(k0, SOFSCL * 0.5 * m / (dt_c * dt_c));
  }

  // Normal force magnitude (>= 0 with damping) of the pair (i, s) at gap g < 0 and normal
  // relative velocity vn; the damping's two-mass spring: the node and the segment's mean nodal mass.
  double normal_force(const SegmentSet& set, std::size_t i, std::size_t s, double k, double g, double vn) const {
    double fn = -k * g;
    if (VDC > 0) {
      const double ms = set.node_mass(i), mm = set.segment_node_mass(s);
      if (ms > 0 && mm > 0) {
        const double omega = std::sqrt(k * (ms + mm) / (ms * mm));
        fn -= VDC / 100.0 * 2.0 * std::min(ms, mm) * omega * vn;
      }
      fn = std::max(fn, 0.0);
    }
    return fn;
  }

  // Friction return map: updates the tangential force ft (N, 3) of the pair for the relative
  // velocity vrel (vn its normal part along the unit normal n) over dt; vt receives the
  // tangential relative velocity (for the frictional work).
  void friction_update(double ft[3], const double n[3], const double vrel[3], double vn, double k, double fn,
                       double dt, double vt[3]) const {
    for (int d = 0; d < 3; ++d) vt[d] = vrel[d] - vn * n[d];
    const double speed = std::sqrt(dot3(vt, vt));
    const double mu = FD + (FS - FD) * std::exp(-DC * speed);
    const double ftn = dot3(ft, n);
    double trial[3];
    for (int d = 0; d < 3; ++d) trial[d] = ft[d] - ftn * n[d] - k * vt[d] * dt;
    const double mag = std::sqrt(dot3(trial, trial)), limit = mu * fn;
    const double scale = mag > limit && mag > 0 ? limit / mag : 1.0;
    for (int d = 0; d < 3; ++d) ft[d] = scale * trial[d];
  }
};

}  // namespace plyimpact::contact
