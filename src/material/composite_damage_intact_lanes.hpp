// *MAT_054 / *MAT_055 for kLanes intact points at once: the update of composite_point_update and
// composite_damage_update for a point that has not failed in any mode and meets no criterion and
// no erosion limit in this cycle, as straight-line lane arithmetic (SIMD over the lanes).
// Why: almost every point of an impact scene is intact almost all the time, and the general point
// update (a scalar call per point, with the degradation box, the return and the failure passes)
// cost about a fifth of the default scene's cycle on one core.
// The arithmetic is that of the general update, expression for expression: GCC contracts
// a * b + c into fused multiply-adds by default (-ffp-contract=fast), and it does so alike in the
// general update and in these lanes as long as the expressions are the same, so a lane's result is
// bit-identical to it. The test Mat054Lanes checks that on random points; a compiler that
// contracted the two differently would differ in the last bits only, and fail that test. A lane
// whose `event` is 1 (a criterion >= 0 or an erosion limit reached) must be redone by the general
// update from its unchanged inputs: this kernel writes nothing but its outputs.
// Not covered (the caller uses the general update for the whole material): EPSF > 0, whose
// transverse shear damage needs the hypotenuse of the general update.
#pragma once

#include <cmath>
#include <limits>

#include "core/lanes.hpp"
#include "material/composite_damage.hpp"

namespace plyimpact::material {

// Whether a material can use the intact lane update at all.
inline bool composite_intact_lanes_apply(const CompositeDamageParams& p) { return p.EPSF == 0; }

// What the intact update reads of each lane's point history (composite_history layout).
struct IntactLaneHistory {
  alignas(64) double eps[6][kLanes];   // total strain, material axes (engineering shear)
  alignas(64) double XT[kLanes], XC[kLanes];
  alignas(64) double crashfront[kLanes];
  alignas(64) double shear_damage[kLanes];  // transverse shear damage d (0 when EPSF = 0)
  alignas(64) double element_dt[kLanes], initial_dt[kLanes];  // TFAIL context
  alignas(64) double erosion_scale[kLanes];  // CompositeDamageContext::erosion_scale
};

// What it gives back: the new stress (global axes), axes, strain and the four criterion values.
struct IntactLaneResult {
  alignas(64) double s[6][kLanes];
  alignas(64) double Qn[9][kLanes];
  alignas(64) double eps[6][kLanes];
  alignas(64) double criteria[4][kLanes];  // fibre t, fibre c, matrix t, matrix c (history kCriteria)
  alignas(64) double event[kLanes];       // 1: a criterion or erosion limit met: general update
};

// out = R T R^T of a symmetric T (Voigt t0..t5) and a row-major R (r0..r8), with rotate_voigt's
// operations in rotate_voigt's order. Scalars only, so the lane loops around it vectorise.
PLYIMPACT_LANE_KERNEL void rotate_voigt_lane(double r0, double r1, double r2, double r3, double r4, double r5,
                                             double r6, double r7, double r8, double t0, double t1, double t2,
                                             double t3, double t4, double t5, double& o0, double& o1, double& o2,
                                             double& o3, double& o4, double& o5) {
  const double a00 = r0 * t0 + r1 * t3 + r2 * t5, a01 = r0 * t3 + r1 * t1 + r2 * t4, a02 = r0 * t5 + r1 * t4 + r2 * t2;
  const double a10 = r3 * t0 + r4 * t3 + r5 * t5, a11 = r3 * t3 + r4 * t1 + r5 * t4, a12 = r3 * t5 + r4 * t4 + r5 * t2;
  const double a20 = r6 * t0 + r7 * t3 + r8 * t5, a21 = r6 * t3 + r7 * t1 + r8 * t4, a22 = r6 * t5 + r7 * t4 + r8 * t2;
  o0 = a00 * r0 + a01 * r1 + a02 * r2;
  o1 = a10 * r3 + a11 * r4 + a12 * r5;
  o2 = a20 * r6 + a21 * r7 + a22 * r8;
  o3 = a00 * r3 + a01 * r4 + a02 * r5;
  o4 = a10 * r6 + a11 * r7 + a12 * r8;
  o5 = a20 * r0 + a21 * r1 + a22 * r2;
}

// sum over a, b of x_a S_ab y_b for a symmetric S (Voigt t0..t5), accumulated from 0 in the order
// a, then b, as composite_point_update's rotation back to global axes.
PLYIMPACT_LANE_KERNEL double voigt_bilinear_lane(double x0, double x1, double x2, double y0, double y1, double y2,
                                                 double t0, double t1, double t2, double t3, double t4, double t5) {
  double sum = 0;
  sum += x0 * t0 * y0, sum += x0 * t3 * y1, sum += x0 * t5 * y2;
  sum += x1 * t3 * y0, sum += x1 * t1 * y1, sum += x1 * t4 * y2;
  sum += x2 * t5 * y0, sum += x2 * t4 * y1, sum += x2 * t2 * y2;
  return sum;
}

// composite_intact_lanes for CRIT 55 (kCrit55) or 54. The card's choices are template arguments or
// a second lane loop rather than selects in the lane body: a select computes both sides, and the
// matrix criterion of the other CRIT, EFS's effective strain and TFAIL's step ratio cost three
// divides and a square root per lane group that most cards never read.
template <bool kCrit55>
PLYIMPACT_LANE_KERNEL void composite_intact_lanes_for(const CompositeDamageParams& p, const LaneVec<9>& Qo,
                                                      const LaneVec<9>& R, const LaneVec<6>& s_old,
                                                      const LaneVec<6>& D, double dt, const IntactLaneHistory& h,
                                                      IntactLaneResult& out) {
  const double* C = p.C.data();
  const double c00 = C[0], c01 = C[1], c02 = C[2], c10 = C[6], c11 = C[7], c12 = C[8];
  const double c20 = C[12], c21 = C[13], c22 = C[14];
  const double inv_gab = 1.0 / p.GAB, alph3 = 3.0 * p.ALPH, gbc = p.GBC, gca = p.GCA;
  const double beta = p.BETA, alph = p.ALPH, gab = p.GAB;
  const double soft_f = p.TFAIL > 0 ? p.SOFT : 1.0, soft_g = p.TFAIL > 0 ? p.SOFTG : 1.0;
  const double YT0 = p.strength.YT, YC0 = p.strength.YC, SC0 = p.strength.SC;
  // Erosion limits of an intact point (erosion_cause) as thresholds a disabled limit never meets, so
  // the lane body tests them without branches.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const bool dfail = p.DFAILT != 0;
  const double DFAILT = dfail ? p.DFAILT : kInf, DFAILC = dfail && p.DFAILC < 0 ? p.DFAILC : -kInf;
  const double DFAILM = dfail && p.DFAILM > 0 ? p.DFAILM : kInf, DFAILS = dfail && p.DFAILS > 0 ? p.DFAILS : kInf;
  const double EFS = p.EFS > 0 ? p.EFS : kInf;
  const double TFAIL_STEP = p.TFAIL > 0 && p.TFAIL <= 0.1 ? p.TFAIL : -kInf;   // element step below
  const double TFAIL_RATIO = p.TFAIL > 0.1 ? p.TFAIL : -kInf;                  // step / initial step below
  PLYIMPACT_LANES {
    const double o0 = Qo[0][l], o1 = Qo[1][l], o2 = Qo[2][l], o3 = Qo[3][l], o4 = Qo[4][l], o5 = Qo[5][l];
    const double o6 = Qo[6][l], o7 = Qo[7][l], o8 = Qo[8][l];
    const double r0 = R[0][l], r1 = R[1][l], r2 = R[2][l], r3 = R[3][l], r4 = R[4][l], r5 = R[5][l];
    const double r6 = R[6][l], r7 = R[7][l], r8 = R[8][l];
    // Q_new = Q_old R^T (rotate_axes): n[3a + j] = o[3a] r[3j] + o[3a+1] r[3j+1] + o[3a+2] r[3j+2].
    const double n0 = o0 * r0 + o1 * r1 + o2 * r2, n1 = o0 * r3 + o1 * r4 + o2 * r5, n2 = o0 * r6 + o1 * r7 + o2 * r8;
    const double n3 = o3 * r0 + o4 * r1 + o5 * r2, n4 = o3 * r3 + o4 * r4 + o5 * r5, n5 = o3 * r6 + o4 * r7 + o5 * r8;
    const double n6 = o6 * r0 + o7 * r1 + o8 * r2, n7 = o6 * r3 + o7 * r4 + o8 * r5, n8 = o6 * r6 + o7 * r7 + o8 * r8;
    // Stress into the old axes, strain increment (engineering shear) into the new ones.
    double sm0, sm1, sm2, sm3, sm4, sm5, dm0, dm1, dm2, dm3, dm4, dm5;
    rotate_voigt_lane(o0, o1, o2, o3, o4, o5, o6, o7, o8, s_old[0][l], s_old[1][l], s_old[2][l], s_old[3][l],
                      s_old[4][l], s_old[5][l], sm0, sm1, sm2, sm3, sm4, sm5);
    rotate_voigt_lane(n0, n1, n2, n3, n4, n5, n6, n7, n8, D[0][l] * dt, D[1][l] * dt, D[2][l] * dt, D[3][l] * dt,
                      D[4][l] * dt, D[5][l] * dt, dm0, dm1, dm2, dm3, dm4, dm5);
    dm3 *= 2, dm4 *= 2, dm5 *= 2;
    (void)sm4, (void)sm5;  // bc and ca are elastic in total form
    const double e0 = h.eps[0][l] + dm0, e1 = h.eps[1][l] + dm1, e2 = h.eps[2][l] + dm2;
    const double e3 = h.eps[3][l] + dm3, e4 = h.eps[4][l] + dm4, e5 = h.eps[5][l] + dm5;
    const bool soft = h.crashfront[l] != 0;
    // Trial stress (every mode intact: the degradation box is unbounded, the projection the identity).
    const double t0 = sm0 + c00 * dm0 + c01 * dm1 + c02 * dm2;
    const double t1 = sm1 + c10 * dm0 + c11 * dm1 + c12 * dm2;
    const double t2 = sm2 + c20 * dm0 + c21 * dm1 + c22 * dm2;
    const double t3 = sm3 + dm3 / (inv_gab + alph3 * sm3 * sm3);
    const double g = (1.0 - h.shear_damage[l]) * (soft ? soft_g : 1.0);
    const double t4 = g * gbc * e4, t5 = g * gca * e5;
    // Criteria (composite_criteria) at the current strengths.
    const double f = soft ? soft_f : 1.0;
    const double XT = f * h.XT[l], XC = f * h.XC[l], YT = f * YT0, YC = f * YC0, SC = f * SC0;
    const double tt = t3 * t3, ss = SC * SC;
    const double tau_bar = (tt / (2 * gab) + 0.75 * alph * tt * tt) / (ss / (2 * gab) + 0.75 * alph * ss * ss);
    // Both branches are computed and one is selected: a division under a condition keeps GCC
    // from vectorising (it may trap), and lanes differ in sign anyway.
    const double rat = t0 / XT, rac = t0 / XC;
    const double fibre = t0 >= 0 ? rat * rat + beta * tau_bar - 1 : rac * rac - 1;
    const double ft = t0 >= 0 ? fibre : -1.0, fc = t0 >= 0 ? -1.0 : fibre;
    double matrix;
    if constexpr (kCrit55) {
      const double yy = YC * YT;
      matrix = t1 * t1 / yy + tau_bar + (YC - YT) * t1 / yy - 1;
    } else {
      const double rt = t1 / YT, hc = t1 / (2 * SC), qc = YC / (2 * SC);
      const double m54t = rt * rt + tau_bar - 1, m54c = hc * hc + (qc * qc - 1) * t1 / YC + tau_bar - 1;
      matrix = t1 >= 0 ? m54t : m54c;
    }
    const double mt = t1 >= 0 ? matrix : -1.0, mc = t1 >= 0 ? -1.0 : matrix;
    const double edt = h.element_dt[l];
    double event = ft >= 0 ? 1.0 : 0.0;
    event = fc >= 0 ? 1.0 : event;
    event = mt >= 0 ? 1.0 : event;
    event = mc >= 0 ? 1.0 : event;
    const double k = h.erosion_scale[l];  // >= 1, so a disabled limit stays infinite
    event = e0 >= DFAILT * k ? 1.0 : event;
    event = e0 <= DFAILC * k ? 1.0 : event;
    event = std::abs(e1) >= DFAILM * k ? 1.0 : event;
    event = 0.5 * std::abs(e3) >= DFAILS * k ? 1.0 : event;
    event = edt > 0 && edt < TFAIL_STEP ? 1.0 : event;
    out.event[l] = event;
    out.criteria[0][l] = ft, out.criteria[1][l] = fc, out.criteria[2][l] = mt, out.criteria[3][l] = mc;
    out.eps[0][l] = e0, out.eps[1][l] = e1, out.eps[2][l] = e2, out.eps[3][l] = e3, out.eps[4][l] = e4, out.eps[5][l] = e5;
    out.Qn[0][l] = n0, out.Qn[1][l] = n1, out.Qn[2][l] = n2, out.Qn[3][l] = n3, out.Qn[4][l] = n4;
    out.Qn[5][l] = n5, out.Qn[6][l] = n6, out.Qn[7][l] = n7, out.Qn[8][l] = n8;
    // Back to global axes with the new axes: s_ij = sum_ab Qn_ai S_ab Qn_bj (columns i, j of Qn).
    out.s[0][l] = voigt_bilinear_lane(n0, n3, n6, n0, n3, n6, t0, t1, t2, t3, t4, t5);
    out.s[1][l] = voigt_bilinear_lane(n1, n4, n7, n1, n4, n7, t0, t1, t2, t3, t4, t5);
    out.s[2][l] = voigt_bilinear_lane(n2, n5, n8, n2, n5, n8, t0, t1, t2, t3, t4, t5);
    out.s[3][l] = voigt_bilinear_lane(n0, n3, n6, n1, n4, n7, t0, t1, t2, t3, t4, t5);
    out.s[4][l] = voigt_bilinear_lane(n1, n4, n7, n2, n5, n8, t0, t1, t2, t3, t4, t5);
    out.s[5][l] = voigt_bilinear_lane(n0, n3, n6, n2, n5, n8, t0, t1, t2, t3, t4, t5);
  }
  if (EFS < kInf || TFAIL_RATIO > -kInf)
    PLYIMPACT_LANES {
      const double e0 = out.eps[0][l], e1 = out.eps[1][l], e2 = out.eps[2][l];
      const double ab = 0.5 * out.eps[3][l], bc = 0.5 * out.eps[4][l], ca = 0.5 * out.eps[5][l];
      const double qe = e0 * e0 + e1 * e1 + e2 * e2 + e0 * e1 + e1 * e2 + e2 * e0 + ab * ab + bc * bc + ca * ca;
      const double effective = std::sqrt(4.0 / 3.0 * qe);
      const double edt = h.element_dt[l], idt = h.initial_dt[l];
      const double ratio = edt / idt;
      double event = out.event[l];
      event = effective >= EFS * h.erosion_scale[l] ? 1.0 : event;
      event = edt > 0 && idt > 0 && ratio < TFAIL_RATIO ? 1.0 : event;
      out.event[l] = event;
    }
}

// Qo: old material axes (rows a, b, c, global components); R: incremental rotation; s_old: stress
// in global axes; D: rate of deformation; dt: the step.
PLYIMPACT_LANE_KERNEL void composite_intact_lanes(const CompositeDamageParams& p, const LaneVec<9>& Qo,
                                                  const LaneVec<9>& R, const LaneVec<6>& s_old,
                                                  const LaneVec<6>& D, double dt, const IntactLaneHistory& h,
                                                  IntactLaneResult& out) {
  if (p.CRIT == 55)
    composite_intact_lanes_for<true>(p, Qo, R, s_old, D, dt, h, out);
  else
    composite_intact_lanes_for<false>(p, Qo, R, s_old, D, dt, h, out);
}

}  // namespace plyimpact::material
