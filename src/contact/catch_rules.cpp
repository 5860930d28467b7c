#include "contact/catch_rules.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>

#include "contact/bonded_interfaces.hpp"

namespace plyimpact::contact {

namespace {

// A node in contact pressed into a concave corner or groove of the surface (the shared node of
// four segments pushed in under an impactor's pole, the bottom of a dent) projects beyond the
// edges of every segment meeting there: each segment's closest point is clamped to the shared
// node or edge, and the MAXPAR range of none covers the node. It is still behind all of them, in
// the region no segment's normal range reaches, so releasing it drops a compressed spring (its
// energy is lost and a penetration is reported). Here it stays on the least penetrated of those
// segments, with the clamped closest point (the force acts at the corner node). Which segments
// meet there: the node's last segment and its neighbours whose closest point is the nearest one
// (within 1e-3 of the segment size). Beside a convex edge (a node sliding off the rim of a block)
// the node is in front of the side face that meets there, so it is released as before; and it is
// held only within the depth the neighbour rule accepts (its depth at the last pass plus the
// one-step catch depth, below the release depth).
long hold_in_concave_corner(const SegmentSet& set, SegmentSearch& search, const SpringHistory& springs,
                            std::size_t i, const double* x, double new_contact_depth, Projection& best) {
  const long last = springs.segment[i];
  const Index node = set.node_id(i);
  const double* p = &x[3 * std::size_t(node)];
  const double last_depth = std::max(-springs.gap[i], 0.0);
  constexpr int kMax = 16;
  long seg[kMax];
  Projection proj[kMax];
  double dist[kMax];
  int n = 0;
  auto add = [&](long s) {
    const Index* q = set.segment_nodes(std::size_t(s));
    if (n == kMax || q[0] == node || q[1] == node || q[2] == node || q[3] == node) return;
    const double* sg = search.record(set, std::size_t(s), x);
    proj[n] = project_to_bilinear(p, sg, search.options().MAXPAR);
    const double d[3] = {p[0] - proj[n].point[0], p[1] - proj[n].point[1], p[2] - proj[n].point[2]};
    dist[n] = std::sqrt(dot3(d, d));
    seg[n++] = s;
  };
  add(last);
  for (const Index* k = set.neighbours_begin(std::size_t(last)); k != set.neighbours_end(std::size_t(last)); ++k) add(*k);
  if (n == 0) return -1;
  double nearest = dist[0];
  for (int k = 0; k < n; ++k) nearest = std::min(nearest, dist[k]);
  const double* a1 = search.record(set, std::size_t(last), x) + 4;
  const double size = 2 * std::sqrt(dot3(a1, a1));
  long held = -1;
  double held_g = 0;
  for (int k = 0; k < n; ++k) {
    if (dist[k] > nearest + 1e-3 * std::max(size, nearest)) continue;
    const double g = proj[k].gap - springs.offset_on(i, seg[k]);
    const double depth = search.record(set, std::size_t(seg[k]), x)[7];
    if (!(g < 0) || -g >= std::min(depth, last_depth + new_contact_depth + 0.02 * depth)) return -1;  // in front, or deep
    if (held < 0 || g > held_g) held = seg[k], held_g = g, best = proj[k];
  }
  return held;
}

}  // namespace

long catch_segment(const SegmentSet& set, SegmentSearch& search, const SpringHistory& springs, std::size_t i,
                   const double* x, Projection& best, double new_contact_depth, const double* v, double dt) {
  const std::span<const Index> cands = search.candidates(i);
  const long last = springs.segment[i];
  if (cands.empty() && last < 0) return -1;  // nothing within reach until the next sort
  const Index node = set.node_id(i);
  const double maxpar = search.options().MAXPAR;
  const double* p = &x[3 * std::size_t(node)];
  const double v_node = v != nullptr ? std::sqrt(dot3(&v[3 * std::size_t(node)], &v[3 * std::size_t(node)])) : 0.0;
  // The node's normal, from its own segments, once a candidate passes the sphere test.
  const double* nn = nullptr;
  double nn_len = -1;
  // The in-plane pre-check assumes |gap| <= release depth, i.e. no initial-penetration offset.
  const bool plain = springs.offset[i] == 0 && springs.exposure_segment[i] < 0;
  // Distance from the closest point to the node beyond |g|: the tangential overshoot of a
  // projection clamped to the edge, at most (MAXPAR - 1) x the longest edge <= 2 r (MAXPAR - 1).
  const double r_factor = 1 + 2 * std::max(maxpar - 1, 0.0);
  long best_s = -1;
  double best_g = 0;
  // Nodes of the segment of the last pass (-1: none). A node in contact slides from its segment to
  // a neighbour (one sharing a node with it) at the depth it has: the neighbour accepts the node's
  // depth at the last pass plus the one-step catch depth. With the catch depth alone a node pressed
  // deeper would be released at every segment boundary it slides across (the contact area grows
  // under a sphere); with the full release depth a node lifting off a top face beside an eroded
  // hole would be caught by the hole's side face (which shares the edge) at its distance from the
  // edge, a spring from nothing (tests ContactPersistence, HoleEdge).
  Index ln[4] = {-1, -1, -1, -1};
  const double last_depth = last >= 0 ? std::max(-springs.gap[i], 0.0) : 0.0;
  if (last >= 0)
    for (int k = 0; k < 4; ++k) ln[k] = set.segment_nodes(std::size_t(last))[k];
  auto shares_node_with_last = [&](const Index* q) {
    bool near = false;
    for (int a = 0; a < 4; ++a) near = near || q[a] == ln[0] || q[a] == ln[1] || q[a] == ln[2] || q[a] == ln[3];
    return near;
  };
  auto consider = [&](Index s) __attribute__((always_inline)) {  // inlined: a few candidates per node
    const double* sg = search.record(set, std::size_t(s), x);  // refreshed at the first look in a pass
    // Bounding sphere: an accepted node lies within r + |g| (+ overshoot) of the centre, |g| below
    // the accepted depth, and it can only beat the best so far if it is less penetrated,
    // |g| < |g_best|. Full release depth on the segment the node was in contact with, its depth at
    // the last pass plus the new-contact depth on the neighbours, the new-contact depth elsewhere
    // (tested first: most candidates fail it).
    const double depth = sg[7];
    const double catch_depth = new_contact_depth + 0.02 * depth;
    const double dx = p[0] - sg[0], dy = p[1] - sg[1], dz = p[2] - sg[2];
    const double d2 = dx * dx + dy * dy + dz * dz, r = r_factor * double(SegmentSearch::radius(sg));
    auto reach = [&](double accept) { return r + (best_s >= 0 ? std::min(accept, -best_g) : accept); };
    const Index* q = set.segment_nodes(std::size_t(s));
    double accept = std::min(depth, catch_depth);
    const double accept_catch = accept;  // what a new contact may be caught at (exposures aside)
    bool exposure = false, neighbour = false;
    if (last >= 0) {
      const double near_depth = s == last ? depth : std::min(depth, last_depth + catch_depth);
      if (const double rn = reach(accept); d2 > rn * rn) {
        const double rf = reach(near_depth);
        if (d2 > rf * rf || !shares_node_with_last(q)) return;
        accept = near_depth;
        neighbour = s != last;
      } else if (shares_node_with_last(q)) {
        accept = near_depth;
        neighbour = s != last;
      }
    } else {
      // First pass after a rebuild: a node new to the surface, or a face erosion exposed, may
      // already lie behind the other side by more than one step's motion (apply books it as an
      // offset, not a spring).
      exposure = springs.exposed_pass && (springs.new_node[i] || springs.new_segment[std::size_t(s)]);
      if (exposure) accept = depth;
      if (const double rn = reach(accept); d2 > rn * rn) return;
    }
    double n0[3];
    cross3(sg + 4, sg + 8, n0);
    float normal_bound[2];  // deviation bound, 1 / |n0|
    std::memcpy(normal_bound, sg + 11, sizeof normal_bound);
    // Bounds of the gap before the projection. With the same terms as below,
    //   (p - c) . n0/|n0| - m^2 |a3 . n0|/|n0| <= gap (n . n0/|n0|) <= (p - c) . n0/|n0| + m^2 |a3 . n0|/|n0|,
    // so a positive lower bound means a node in front of the segment, and a negative upper bound
    // u means gap <= u (n . n0/|n0| <= 1), a node at least |u| behind it. A plain node (gap = g) is
    // caught at neither, in front nor deeper than `accept`; the margin of 1e-6 r covers the
    // Newton projection's round-off. Spares the projections of inter-ply single surface contact,
    // where each ply node lies over or under the faces of every ply within a segment's reach
    // (first after the sphere test: the slab it leaves is what rejects most of those).
    if (plain && double(normal_bound[0]) < 1) {
      const double along = dx * n0[0] + dy * n0[1] + dz * n0[2], warp = maxpar * maxpar * std::abs(dot3(n0, sg + 12));
      const double inv = double(normal_bound[1]), margin = 1e-6 * r;
      if ((along - warp) * inv > margin || (along + warp) * inv < -accept - margin) return;
    }
    if (q[0] == node || q[1] == node || q[2] == node || q[3] == node) return;
    if (set.single()) {
      const Index* o = set.segment_owner(std::size_t(s));
      bool own = false;
      for (int k = 0; k < 8; ++k) own = own || o[k] == node;
      if (own) return;
    }
    if (set.bonded() != nullptr && set.bonded()->excludes(node, q)) return;  // a tiebreak holds the pair
    if (nn_len < 0) {
      nn = search.node_normal(set, i, x);
      nn_len = std::sqrt(dot3(nn, nn));
    }
    // Orientation pre-check with the segment's centre normal, made conservative by the bound of
    // the normal's deviation over the segment: it skips only what the exact check below would skip
    // (a node beside a side face it cannot push through), without the projection.
    if (nn_len > 0 && dot3(nn, n0) * double(normal_bound[1]) > (-0.3 + double(normal_bound[0])) * nn_len) return;
    // Can it beat the best so far (g > g_best)? An accepted node has a negative gap, p - c =
    // xi a1 + eta a2 + xi eta a3 + gap n with |xi|, |eta| <= m, and 0 < n . n0/|n0| <= 1 (normal
    // deviation bound < 1), so gap <= gap (n . n0/|n0|) = (p - c) . n0/|n0| - xi eta a3 . n0/|n0|
    // <= (p - c) . n0/|n0| + m^2 |a3 . n0|/|n0|. A node on the shared corner of several segments of
    // a flat surface (matching meshes) then projects onto the first only: the others tie.
    if (best_s >= 0 && double(normal_bound[0]) < 1) {
      const double m = maxpar, inv = 1 / std::sqrt(dot3(n0, n0));
      const double upper = (dx * n0[0] + dy * n0[1] + dz * n0[2] + m * m * std::abs(dot3(n0, sg + 12))) * inv;
      if (upper - springs.offset_on(i, s) <= best_g) return;
    }
    // In-plane pre-check (refresh_segment): a node the projection would accept has
    // |(p - c) . a1| <= bound_xi and |(p - c) . a2| <= bound_eta; two dot products instead of the
    // Newton projection of a neighbour the node lies beside (about half the projections).
    if (plain) {
      float bound[2];
      std::memcpy(bound, sg + 15, sizeof bound);
      if (std::abs(dx * sg[4] + dy * sg[5] + dz * sg[6]) > double(bound[0]) ||
          std::abs(dx * sg[8] + dy * sg[9] + dz * sg[10]) > double(bound[1]))
        return;
    }
    const Projection pr = project_to_bilinear(p, sg, maxpar);
    if (!pr.inside) return;
    // Orientation: the node's own surface must face the segment (normals at more than ~107 deg),
    // so a node at a corner is not pushed out through a side face it merely slid under.
    if (nn_len > 0 && dot3(nn, pr.normal) > -0.3 * nn_len) return;
    const double g = pr.gap - springs.offset_on(i, s);
    // A node with an exposure offset stays on that segment while it is behind the face (the offset
    // relaxes as it backs out: apply), not only while it is deeper than the offset.
    const bool relaxing = s == springs.exposure_segment[i] && pr.gap - springs.offset[i] < 0;
    if ((!(g < 0) && !relaxing) || g <= -accept) return;
    // Deeper than a step's motion behind an exposed face only if within the face proper: beside
    // its edge (inside only by the MAXPAR tolerance) it is a node next to a hole, not behind a face.
    if (exposure && g <= -accept_catch && (std::abs(pr.xi) > 1 || std::abs(pr.eta) > 1)) return;
    // The catch depth above bounds the relative motion by the fastest contact node anywhere (one
    // number for the sphere tests); a flying fragment then lets a slow node be caught tens of um
    // deep, a spring nobody compressed. The node can only have
    // crossed this segment by its own and the segment nodes' motion in the step.
    if (v != nullptr && s != last && !exposure) {  // a neighbour switch or a new contact
      double vq2 = 0;
      for (int a = 0; a < 4; ++a) vq2 = std::max(vq2, dot3(&v[3 * std::size_t(q[a])], &v[3 * std::size_t(q[a])]));
      const double crossed = 2 * dt * (v_node + std::sqrt(vq2)) + 0.02 * depth;
      if (g <= -std::min(depth, neighbour ? last_depth + crossed : crossed)) return;
    }
    // Beside the face (inside it only by the MAXPAR margin) and already behind its plane before
    // this step's motion, deeper than its old spring: the node did not cross this face, it slid
    // along under its edge (an impactor node in an eroded hole reaching the rim, a few um below the
    // plane of the face around it). It is not in contact with this face; the hole's wall, if it
    // meets it, is its contact.
    if (v != nullptr && s != last && (std::abs(pr.xi) > 1 || std::abs(pr.eta) > 1)) {
      double vn = 0;
      for (int d = 0; d < 3; ++d) {
        double vr = v[3 * std::size_t(node) + d];
        for (int a = 0; a < 4; ++a) vr -= pr.N[a] * v[3 * std::size_t(q[a]) + d];
        vn += vr * pr.normal[d];
      }
      if (g - vn * dt < (last < 0 ? 0.0 : std::min(springs.gap[i], 0.0))) return;
    }
    // The nearest surface wins: the least penetrated segment (ties: the one met first, the
    // segment of the last pass).
    if (best_s < 0 || g > best_g) {
      best = pr;
      best_s = s;
      best_g = g;
    }
  };
  // The segment of the last pass first. Its neighbours take the full release depth; the node's
  // list covers them only within the new-contact depth: search them here unless the node was
  // caught at most that deep on its segment (then anything less penetrated is in the list).
  if (last >= 0) {
    consider(Index(last));
    if (best_s < 0 || -best_g > search.new_depth_cap())
      for (const Index* k = set.neighbours_begin(std::size_t(last)); k != set.neighbours_end(std::size_t(last)); ++k)
        consider(*k);
  }
  for (const Index s : cands)
    if (s != last) consider(s);
  if (best_s < 0 && last >= 0 && last_depth > 0) 
    best_s = hold_in_concave_corner(set, search, springs, i, x, new_contact_depth, best);
  return best_s;
}

}  // namespace plyimpact::contact
