#include "contact/stiffness_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "contact/parallel_items.hpp"

namespace plyimpact::contact {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Per side: the stiffest and heaviest segments, the softest finite one, and whether a segment
// without an element (impactor surface) is there.
struct SideSegments {
  double k_max[2] = {0, 0}, mass_max[2] = {0, 0};
  double k_fin_min = kInf;
  bool k_inf[2] = {false, false};
};

SideSegments side_segments(const SegmentSet& set) {
  const std::size_t S = set.num_segments();
  double k_max[2] = {0, 0}, mass_max[2] = {0, 0}, k_fin_min = kInf;
  int k_inf[2] = {0, 0};
#pragma omp parallel for schedule(static) if (parallel_items(S)) \
    reduction(max : k_max[:2], mass_max[:2], k_inf[:2]) reduction(min : k_fin_min)
  for (long i = 0; i < long(S); ++i) {
    const std::size_t s = std::size_t(i);
    const int side = set.segment_side(s);
    const double k = set.segment_stiffness(s);
    if (!std::isfinite(k)) k_inf[side] = 1;
    if (std::isfinite(k)) {
      k_max[side] = std::max(k_max[side], k);
      k_fin_min = std::min(k_fin_min, k);
    }
    mass_max[side] = std::max(mass_max[side], set.segment_mass(s));
  }
  SideSegments r;
  for (int side = 0; side < 2; ++side) {
    r.k_max[side] = k_max[side];
    r.mass_max[side] = mass_max[side];
    r.k_inf[side] = k_inf[side] != 0;
  }
  r.k_fin_min = k_fin_min;
  return r;
}

void stiffness_range(const SegmentSet& set, const PenaltyLaw& law, const SideSegments& segs, StiffnessBounds& b) {
  double k_min = kInf, k_max = 0;
  const std::size_t N = set.num_nodes();
#pragma omp parallel for schedule(static) if (parallel_items(N)) reduction(min : k_min) reduction(max : k_max)
  for (long node = 0; node < long(N); ++node) {
    const std::size_t i = std::size_t(node);
    const int other = set.other_side(i);
    const double k_node = set.node_stiffness(i);
    double k_lo = 0, k_hi = 0;
    // PENOPT 1: k0 = min(k_node, k_segment) <= min(k_node, stiffest segment of the other side); a
    // stiff node against a soft surface gets the surface's stiffness, not its own.
    const double k_seg_hi = segs.k_inf[other] ? kInf : segs.k_max[other];
    double k0_hi = std::min(k_node, k_seg_hi);
    if (!std::isfinite(k0_hi)) k0_hi = std::isfinite(k_node) ? k_node : segs.k_max[other];
    const double k0_lo = std::isfinite(k_node) ? std::min(k_node, segs.k_fin_min) : segs.k_fin_min;
    if (law.SOFT == 0) {
      k_lo = k0_lo;
      k_hi = k0_hi;
    } else if (law.SOFT == 1) {
      const double soft = law.SOFSCL * 0.5 * set.node_mass(i) / (law.dt_c * law.dt_c);
      k_lo = std::max(k0_lo, 0.0);
      k_hi = std::max(k0_hi, soft);
      k_lo = std::max(k_lo == kInf ? 0.0 : k_lo, std::min(soft, k_hi));
    } else {
      const double sf = law.scale(set.node_side(i));
      const double m1 = set.node_segment_mass(i), m2 = segs.mass_max[other];
      k_hi = m1 + m2 > 0 ? 0.5 * sf * m1 * m2 / (m1 + m2) / (law.dt_c * law.dt_c) : 0.0;
      k_lo = k_hi;
    }
    if (!(k_hi > 0) || !std::isfinite(k_hi)) continue;
    k_min = std::min(k_min, k_lo > 0 && std::isfinite(k_lo) ? k_lo : k_hi);
    k_max = std::max(k_max, k_hi);
  }
  b.k_min = std::isfinite(k_min) ? k_min : 0;
  b.k_max = k_max;
}

}  // namespace

StiffnessBounds stiffness_bounds(const SegmentSet& set, const PenaltyLaw& law, const std::vector<double>& mass) {
  StiffnessBounds b;
  const SideSegments segs = side_segments(set);
  stiffness_range(set, law, segs, b);

  // Stable step of the stiffest pair. A spring k between node i (mass m_i) and a point of segment
  // s (weights N_a, sum 1, on nodes of mass m_a) has omega^2 <= k (1/m_i + sum N_a^2 / m_a)
  // <= k / m_i + k / m_s, m_s the lightest deformable node of s; rigid nodes count as infinitely
  // heavy. So omega^2 <= max_i A_i + max_s B_s with k bounded once by node-only and once by
  // segment-only quantities (A_i: k <= its bound from the node's side, B_s: from the segment's):
  //   SOFT 0: k = min(k_i, k_s) <= min(k_i, max k_s) and <= min(k_s, max k_i)
  //   SOFT 1: k = max(that, SOFSCL 0.5 min(m_i, m_seg) / dt_c^2), m_seg <= its own value
  //   SOFT 2: k = 0.5 sf m1 m2 / (m1 + m2) / dt_c^2 <= 0.5 sf min(m1, m2) / dt_c^2
  // This pairs the stiffness and mass of the same node or segment, instead of the stiffest spring
  // anywhere with the lightest node anywhere (far too small a step on a graded mesh).
  const double dt2 = law.dt_c * law.dt_c;
  const std::size_t S = set.num_segments(), N = set.num_nodes();
  double sn_k_max[2] = {0, 0}, sn_segm_max[2] = {0, 0}, sf_max[2] = {0, 0};
  int sn_k_inf[2] = {0, 0};
#pragma omp parallel for schedule(static) if (parallel_items(N)) \
    reduction(max : sn_k_max[:2], sn_segm_max[:2], sf_max[:2], sn_k_inf[:2])
  for (long node = 0; node < long(N); ++node) {
    const std::size_t i = std::size_t(node);
    const int side = set.node_side(i);
    if (std::isfinite(set.node_stiffness(i))) sn_k_max[side] = std::max(sn_k_max[side], set.node_stiffness(i));
    else sn_k_inf[side] = 1;
    sn_segm_max[side] = std::max(sn_segm_max[side], set.node_segment_mass(i));
    sf_max[side] = std::max(sf_max[side], law.scale(side));
  }
  auto finite_or_zero = [](double k) { return std::isfinite(k) ? k : 0.0; };
  double A[2] = {0, 0}, B[2] = {0, 0};  // A[side]: contact nodes of that side; B[side]: its segments
#pragma omp parallel for schedule(static) if (parallel_items(N)) reduction(max : A[:2])
  for (long node = 0; node < long(N); ++node) {
    const std::size_t i = std::size_t(node);
    const double m_i = set.node_mass(i);
    if (set.node_rigid(set.node_id(i)) || !(m_i > 0)) continue;
    const int side = set.node_side(i), other = set.other_side(i);
    double k;
    if (law.SOFT == 2) {
      k = 0.5 * law.SLSFAC * (side == 0 ? law.SFS : law.SFM) * std::min(set.node_segment_mass(i), segs.mass_max[other]) / dt2;
    } else {
      k = finite_or_zero(std::min(set.node_stiffness(i), segs.k_inf[other] ? kInf : segs.k_max[other]));
      if (law.SOFT == 1) k = std::max(k, law.SOFSCL * 0.5 * m_i / dt2);
    }
    A[side] = std::max(A[side], k / m_i);
  }
#pragma omp parallel for schedule(static) if (parallel_items(S)) reduction(max : B[:2])
  for (long seg = 0; seg < long(S); ++seg) {
    const std::size_t s = std::size_t(seg);
    double m_s = kInf;
    for (int a = 0; a < 4; ++a) {
      const Index n = set.segment_nodes(s)[a];
      if (!set.node_rigid(n) && mass[n] > 0) m_s = std::min(m_s, mass[n]);
    }
    if (!std::isfinite(m_s)) continue;
    const int side = set.segment_side(s), slaves = set.single() ? 0 : 1 - side;
    double k;
    if (law.SOFT == 2) {
      k = 0.5 * sf_max[slaves] * std::min(set.segment_mass(s), sn_segm_max[slaves]) / dt2;
    } else {
      k = finite_or_zero(std::min(set.segment_stiffness(s), sn_k_inf[slaves] ? kInf : sn_k_max[slaves]));
      if (law.SOFT == 1) k = std::max(k, law.SOFSCL * 0.5 * set.segment_node_mass(s) / dt2);
    }
    B[side] = std::max(B[side], k / m_s);
  }
  double omega2 = 0;
  for (int side = 0; side < (set.single() ? 1 : 2); ++side) {
    const int other = set.single() ? 0 : 1 - side;
    omega2 = std::max(omega2, A[side] + B[other]);
  }
  if (omega2 > 0) b.dt_stable = 2.0 / std::sqrt(omega2);
  return b;
}

}  // namespace plyimpact::contact
