#include "contact/segment_search.hpp"

#include <algorithm>
#include <cmath>

#include "contact/parallel_items.hpp"

namespace plyimpact::contact {

void SegmentSearch::reset(const SegmentSet& set, const double* x) {
  // Each segment's box is expanded by its own margin: release depth (the deepest accepted
  // penetration), 5 % of its extent (MAXPAR) and the motion allowance. Allowance and bucket edge
  // follow the median segment extent, not the largest, so a graded mesh (a fine impact zone in a
  // coarse plate) does not put the whole fine zone into one bucket; a large segment is simply
  // listed in every bucket its box overlaps.
  const std::size_t S = set.num_segments();
  std::vector<double> extent(S, 0.0);
  const long n_segments = long(S);
#pragma omp parallel for schedule(static) if (parallel_items(S))
  for (long i = 0; i < n_segments; ++i) {
    const std::size_t s = std::size_t(i);
    const Index* q = set.segment_nodes(s);
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        double d2 = 0;
        for (int d = 0; d < 3; ++d) {
          const double e = x[3 * std::size_t(q[a]) + d] - x[3 * std::size_t(q[b]) + d];
          d2 += e * e;
        }
        extent[s] = std::max(extent[s], std::sqrt(d2));
      }
  }
  double median = 0;
  if (S > 0) {
    std::vector<double> sorted = extent;
    std::nth_element(sorted.begin(), sorted.begin() + S / 2, sorted.end());
    median = sorted[S / 2];
  }
  // A sixteenth of the median extent: short lists against frequent sorts. Measured on the default
  // scene (BENCHMARKS.md, "The whole event on one core below 150 ns per element-cycle"): a quarter, an eighth, a sixteenth and a 32nd gave
  // contact 4.9, 3.4, 3.0 and 3.1 s over its first millisecond, the same springs in every cycle.
  allowance_ = median / 16;
  margin_.resize(S);
  for (std::size_t s = 0; s < S; ++s) margin_[s] = set.release_depth(s) + 0.05 * extent[s] + allowance_;
  // Bucket edge = median extent: a segment's expanded box then spans a few buckets, and a node's
  // bucket holds few segments (measured: 10-15 % faster than an edge of extent + 2 margins).
  cell_ = median;
  records_.assign(kRecord * S, 0.0);  // stamps 0: stale (pass_ starts at 1)
  for (std::size_t s = 0; s < S; ++s) records_[kRecord * s + 7] = set.release_depth(s);  // constant; the rest per pass
  for (auto& ids : side_segs_) ids.clear();
  for (std::size_t s = 0; s < S; ++s) side_segs_[set.single() ? 0 : set.segment_side(s)].push_back(Index(s));
  node_normals_.assign(3 * set.num_nodes(), 0.0);
  x_sort_.assign(3 * set.num_force_nodes(), 0.0);
}

PassMotion SegmentSearch::begin_pass(const SegmentSet& set, const double* x, const double* v) {
  ++cycles_since_sort_;
  ++pass_;  // every record is stale until first looked at
  const std::vector<Index>& nodes = set.force_nodes();
  const long U = long(nodes.size());
  double moved2 = 0, v_max2 = 0;  // maxima: exact, whatever the order
#pragma omp parallel for schedule(static) reduction(max : moved2, v_max2) if (parallel_items(nodes.size()))
  for (long u = 0; u < U; ++u) {
    const std::size_t node = std::size_t(nodes[std::size_t(u)]);
    const double* p = &x[3 * node];
    const double* vu = &v[3 * node];
    const double* q = &x_sort_[3 * std::size_t(u)];
    const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
    moved2 = std::max(moved2, dx * dx + dy * dy + dz * dz);
    v_max2 = std::max(v_max2, dot3(vu, vu));
  }
  return {v_max2, moved2};
}

void SegmentSearch::sort(const SegmentSet& set, const double* x, double step_depth, bool full_depth) {
  // The lists are built for the motion expected before the next sort, not for the whole bucket
  // allowance: a node moving at the present largest speed covers BSORT dt v_max = BSORT
  // step_depth / 4 until the next sort, an eighth of this list allowance (a re-sort comes first if
  // it moves a quarter: sort_due), at least a fifth of the bucket allowance (fewer sorts by motion).
  // Without an interval (BSORT 0) only motion triggers a sort: the whole bucket allowance.
  // They hold the segments a node can newly catch within the new-contact depth (catch_rules),
  // whose bound until the next sort is twice the present one (a re-sort comes first if the
  // motion per step grows beyond it), at least an eighth of the list allowance.
  list_allowance_ = options_.BSORT > 0
                        ? std::min(allowance_, std::max(0.2 * allowance_, 2.0 * double(options_.BSORT) * step_depth))
                        : allowance_;
  new_depth_cap_ = std::max(2 * step_depth, 0.125 * list_allowance_);
  double node_box[2][6];
  querying_node_boxes(set, x, node_box);
  // One grid per side (two-way contact): a contact node only walks the other side's segments.
  for (int side = 0; side < (set.single() ? 1 : 2); ++side) {
    segment_boxes(set, side, x, node_box[side]);
    grid_[side].build(boxes_[side], cell_, keep_[side]);
  }
  const std::vector<Index>& nodes = set.force_nodes();
  const long U = long(nodes.size());
#pragma omp parallel for schedule(static) if (parallel_items(nodes.size()))
  for (long u = 0; u < U; ++u)
    for (int d = 0; d < 3; ++d) x_sort_[3 * std::size_t(u) + d] = x[3 * std::size_t(nodes[std::size_t(u)]) + d];
  cycles_since_sort_ = 0;
  ++sorts_;
  refresh_listed(set, x);
  build_candidates(set, x, full_depth);
}

void SegmentSearch::querying_node_boxes(const SegmentSet& set, const double* x, double (&box)[2][6]) const {
  // Per side, the bounding box of the contact nodes that search that side's segments.
  for (auto& b : box) b[0] = b[1] = b[2] = 1e300, b[3] = b[4] = b[5] = -1e300;
  const std::size_t N = set.num_nodes();
  for (int side = 0; side < (set.single() ? 1 : 2); ++side) {
    double lo0 = 1e300, lo1 = 1e300, lo2 = 1e300, hi0 = -1e300, hi1 = -1e300, hi2 = -1e300;  // exact in any order
#pragma omp parallel for schedule(static) if (parallel_items(N)) reduction(min : lo0, lo1, lo2) \
    reduction(max : hi0, hi1, hi2)
    for (long il = 0; il < long(N); ++il) {
      const std::size_t i = std::size_t(il);
      if (set.other_side(i) != side) continue;
      const double* p = &x[3 * std::size_t(set.node_id(i))];
      lo0 = std::min(lo0, p[0]), lo1 = std::min(lo1, p[1]), lo2 = std::min(lo2, p[2]);
      hi0 = std::max(hi0, p[0]), hi1 = std::max(hi1, p[1]), hi2 = std::max(hi2, p[2]);
    }
    box[side][0] = lo0, box[side][1] = lo1, box[side][2] = lo2, box[side][3] = hi0, box[side][4] = hi1, box[side][5] = hi2;
  }
}

void SegmentSearch::segment_boxes(const SegmentSet& set, int side, const double* x, const double (&nodes)[6]) {
  // Each segment's box (its nodes' box expanded by its margin) for the grid, and whether any node
  // that searches this side can pass build_candidates' sphere test on it before the next sort. The
  // test accepts |p - c| <= r_factor (r + a/2) + depth + a/2 with depth <= the release depth, and
  // the centre c lies in the segment's node box, whose diagonal bounds the radius r; a segment
  // whose node box, widened by that reach, misses the querying nodes' box is in no list, so it is
  // left out of the buckets (and of the refresh at the sort), which changes no list. In an impact
  // the plate's faces far from the tup are all such segments.
  const auto& ids = side_segs_[side];
  auto& boxes = boxes_[side];
  auto& keep = keep_[side];
  boxes.resize(6 * ids.size());
  keep.resize(ids.size());
  const double r_factor = 1 + 2 * std::max(options_.MAXPAR - 1, 0.0), half_a = 0.5 * list_allowance_;
  const long J = long(ids.size());
#pragma omp parallel for schedule(static) if (parallel_items(ids.size()))
  for (long jl = 0; jl < J; ++jl) {
    const std::size_t j = std::size_t(jl), s = std::size_t(ids[j]);
    const Index* q = set.segment_nodes(s);
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) {
        const double c = x[3 * std::size_t(q[k]) + d];
        lo[d] = std::min(lo[d], c);
        hi[d] = std::max(hi[d], c);
      }
    double* b = &boxes[6 * j];
    double diag2 = 0;
    for (int d = 0; d < 3; ++d) {
      b[d] = lo[d] - margin_[s];
      b[3 + d] = hi[d] + margin_[s];
      diag2 += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    }
    // Widened by 1e-6 for the radius kept as a float rounded up.
    const double reach = (r_factor * (std::sqrt(diag2) + half_a) + set.release_depth(s) + half_a) * (1 + 1e-6);
    bool meets = true;
    for (int d = 0; d < 3; ++d) meets = meets && lo[d] - reach <= nodes[3 + d] && hi[d] + reach >= nodes[d];
    keep[j] = meets ? 1 : 0;
  }
}

void SegmentSearch::refresh_listed(const SegmentSet& set, const double* x) {
  // The records build_candidates reads; every other record is refreshed where it is read (record()).
  for (int side = 0; side < (set.single() ? 1 : 2); ++side) {
    const auto& ids = side_segs_[side];
    const auto& keep = keep_[side];
    const long J = long(ids.size());
#pragma omp parallel for schedule(static) if (parallel_items(ids.size()))
    for (long j = 0; j < J; ++j)
      if (keep[std::size_t(j)]) refresh_segment(set, std::size_t(ids[std::size_t(j)]), x);
  }
}

void SegmentSearch::build_candidates(const SegmentSet& set, const double* x, bool full_depth) {
  // Until the next sort every contact node moves less than a / 4 from where it is now (the re-sort
  // test), a = the list allowance (sort): a node-to-centre distance changes by at most a / 2 and a
  // bounding radius grows by at most a / 2. The catch rules' sphere test accepts at most
  // |p - c| <= r_factor r + D, D the depth accepted for a new contact (at most
  // min(depth, cap + 2 % depth) until the next sort; the full depth when `full_depth`), so a
  // segment with
  //   |p - c| > r_factor (r + a / 2) + D + a / 2   now
  // cannot pass it before the next sort and is left out of the node's list. The full release
  // depth of a node already in contact is searched on its segment's neighbours (catch_rules), not
  // here: a list sized for it would hold every segment within ~0.4 element of the node, and make
  // nodes a plate's thickness away from the other surface search and refresh every cycle.
  // What remains is the node's bucket filtered to its neighbourhood, in bucket order.
  // Per fixed chunk of nodes into the chunk's own buffer (kept between sorts, so no allocation
  // once sizes settle), then the chunks concatenated in order: the lists are the same for any
  // thread count.
  const std::size_t N = set.num_nodes();
  const double r_factor = 1 + 2 * std::max(options_.MAXPAR - 1, 0.0), half_a = 0.5 * list_allowance_;
  const long chunks = long((N + kListChunk - 1) / kListChunk);
  cand_start_.resize(N + 1);
  if (chunk_cand_.size() < std::size_t(chunks)) chunk_cand_.resize(std::size_t(chunks));
#pragma omp parallel for schedule(dynamic) if (parallel_items(N))
  for (long c = 0; c < chunks; ++c) {
    std::vector<Index>& out = chunk_cand_[std::size_t(c)];
    out.clear();
    const std::size_t end = std::min(N, std::size_t(c + 1) * kListChunk);
    for (std::size_t i = std::size_t(c) * kListChunk; i < end; ++i) {
      cand_start_[i] = Index(out.size());  // relative to the chunk until the concatenation
      const double* p = &x[3 * std::size_t(set.node_id(i))];
      const int gs = set.other_side(i);
      const std::vector<Index>& ids = side_segs_[gs];
      for (Index k : grid_[gs].candidates(p)) {
        const std::size_t s = std::size_t(ids[std::size_t(k)]);
        const double* g = &records_[kRecord * s];
        const double depth = full_depth ? g[7] : std::min(g[7], new_depth_cap_ + 0.02 * g[7]);
        const double dx = p[0] - g[0], dy = p[1] - g[1], dz = p[2] - g[2];
        const double reach = r_factor * (double(radius(g)) + half_a) + depth + half_a;
        if (dx * dx + dy * dy + dz * dz > reach * reach) continue;
        out.push_back(Index(s));
      }
    }
  }
  std::size_t total = 0;
  for (long c = 0; c < chunks; ++c) total += chunk_cand_[std::size_t(c)].size();
  cand_.resize(total);
  std::size_t at = 0;
  for (long c = 0; c < chunks; ++c) {
    const std::vector<Index>& in = chunk_cand_[std::size_t(c)];
    const std::size_t end = std::min(N, std::size_t(c + 1) * kListChunk);
    for (std::size_t i = std::size_t(c) * kListChunk; i < end; ++i) cand_start_[i] += Index(at);
    std::copy(in.begin(), in.end(), cand_.begin() + long(at));
    at += in.size();
  }
  cand_start_[N] = Index(at);
}

void SegmentSearch::refresh_segment(const SegmentSet& set, std::size_t s, const double* x) {
  // Coefficient form, bounding sphere (centre c, largest corner distance) and the normal bound:
  // t_xi x t_eta = n0 + xi u + eta w with n0 = a1 x a2, u = a1 x a3, w = a3 x a2 (linear: the
  // xi eta term is a3 x a3 = 0), so over the segment |n - n0| <= |u| + |w| =: E and the unit
  // normal deviates from n0 / |n0| by at most 2 E / |n0| (|a/|a| - b/|b|| <= 2 |a - b| / |b|).
  double* g = &records_[kRecord * s];
  const Index* q = set.segment_nodes(s);
  const double* p0 = &x[3 * std::size_t(q[0])];
  const double* p1 = &x[3 * std::size_t(q[1])];
  const double* p2 = &x[3 * std::size_t(q[2])];
  const double* p3 = &x[3 * std::size_t(q[3])];
  bilinear_coefficients(p0, p1, p2, p3, g);
  double r2 = 0;
  for (const double* pk : {p0, p1, p2, p3}) {
    const double dx = pk[0] - g[0], dy = pk[1] - g[1], dz = pk[2] - g[2];
    r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
  }
  // Radius as a float rounded up (the sphere tests stay conservative) beside this pass's stamp.
  const float r = std::nextafter(float(std::sqrt(r2)), std::numeric_limits<float>::infinity());
  std::memcpy(g + 3, &r, sizeof r);
  // In-plane bounds for the catch rules' pre-check. A node the projection accepts is
  // p = x(xi, eta) + gap n with |xi|, |eta| <= m = MAXPAR, |gap| <= release depth D, and n normal
  // to t_xi = a1 + eta a3 (so n . a1 = -eta n . a3). Hence
  //   |(p - c) . a1| = |xi a1.a1 + eta a1.a2 + xi eta a1.a3 + gap n.a1|
  //                  <= m (|a1|^2 + |a1.a2| + m |a1.a3|) + D m |a3|,
  // and likewise for a2. Stored as two floats in slot 15, rounded up.
  {
    const double m = options_.MAXPAR, a12 = std::abs(dot3(g + 4, g + 8)), tw = g[7] * m * std::sqrt(dot3(g + 12, g + 12));
    const double b_xi = m * (dot3(g + 4, g + 4) + a12 + m * std::abs(dot3(g + 4, g + 12))) + tw;
    const double b_eta = m * (dot3(g + 8, g + 8) + a12 + m * std::abs(dot3(g + 8, g + 12))) + tw;
    const float bound[2] = {float(b_xi * (1 + 1e-6)), float(b_eta * (1 + 1e-6))};
    std::memcpy(g + 15, bound, sizeof bound);
  }
  double n0[3], u[3], w[3];
  cross3(g + 4, g + 8, n0);
  cross3(g + 4, g + 12, u);
  cross3(g + 12, g + 8, w);
  const double len = std::sqrt(dot3(n0, n0));
  // Stored as floats: the bound rounded up and widened by 1e-6, which also covers the relative
  // error of 1 / |n0| in float (the pre-check then still skips only what the exact check skips).
  float normal_bound[2] = {2.0f, 0.0f};  // degenerate: no orientation pre-check
  if (len > 0) {
    normal_bound[0] = float(std::min(2.0, 2 * (std::sqrt(dot3(u, u)) + std::sqrt(dot3(w, w))) / len) * (1 + 1e-6) + 1e-6);
    normal_bound[1] = float(1 / len);
  }
  std::memcpy(g + 11, normal_bound, sizeof normal_bound);
  __atomic_store_n(stamp_word(g), pass_, __ATOMIC_RELEASE);  // last: a reader seeing it sees the record
}

void SegmentSearch::refresh_claimed(const SegmentSet& set, std::size_t s, const double* x) {
  StampWord* w = stamp_word(&records_[kRecord * s]);
  std::uint32_t seen = __atomic_load_n(w, __ATOMIC_ACQUIRE);
  while (seen != pass_) {
    if (seen != kRefreshing) {
      if (__atomic_compare_exchange_n(w, &seen, kRefreshing, false, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE)) {
        refresh_segment(set, s, x);
        return;
      }
    } else {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
      seen = __atomic_load_n(w, __ATOMIC_ACQUIRE);
    }
  }
}

void SegmentSearch::refresh_all(const SegmentSet& set, const double* x) {
  // Each record and node normal is written by one iteration: no claiming needed.
  const long S = long(set.num_segments()), N = long(set.num_nodes());
#pragma omp parallel if (parallel_items(std::size_t(S + N)))
  {
#pragma omp for schedule(static)
    for (long s = 0; s < S; ++s) refresh_segment(set, std::size_t(s), x);
#pragma omp for schedule(static)
    for (long i = 0; i < N; ++i) node_normal(set, std::size_t(i), x);
  }
}

const double* SegmentSearch::node_normal(const SegmentSet& set, std::size_t i, const double* x) {
  // Sum over the node's own segments of x_13 x x_24 = 8 a1 x a2 (twice the area times the mean
  // normal), in ascending segment order.
  double* nn = &node_normals_[3 * i];
  nn[0] = nn[1] = nn[2] = 0;
  for (const Index* k = set.own_begin(i); k != set.own_end(i); ++k) {
    const double* g = record(set, std::size_t(*k), x);
    double n[3];
    cross3(g + 4, g + 8, n);
    for (int d = 0; d < 3; ++d) nn[d] += 8 * n[d];
  }
  return nn;
}

long SegmentSearch::nearest_segment(const SegmentSet& set, std::size_t i, const double* x, double max_distance,
                                    Projection& best) {
  const Index node = set.node_id(i);
  const double* p = &x[3 * std::size_t(node)];
  const double r_factor = 1 + 2 * std::max(options_.MAXPAR - 1, 0.0);
  long best_s = -1;
  double best_d = 0;
  for (Index s : candidates(i)) {
    const double* g = record(set, std::size_t(s), x);
    const double accept = std::min(max_distance, g[7]);
    const double dx = p[0] - g[0], dy = p[1] - g[1], dz = p[2] - g[2];
    const double reach = r_factor * double(radius(g)) + accept;
    if (dx * dx + dy * dy + dz * dz > reach * reach) continue;
    const Index* q = set.segment_nodes(std::size_t(s));
    if (q[0] == node || q[1] == node || q[2] == node || q[3] == node) continue;
    if (set.single()) {
      const Index* o = set.segment_owner(std::size_t(s));
      if (std::find(o, o + 8, node) != o + 8) continue;  // the node's own element
    }
    const Projection pr = project_to_bilinear(p, g, options_.MAXPAR);
    const double d = std::abs(pr.gap);
    if (!pr.inside || d > accept) continue;
    if (best_s < 0 || d < best_d) {
      best = pr;
      best_s = s;
      best_d = d;
    }
  }
  return best_s;
}

void SegmentSearch::visit_state(StateVisitor& v) {
  StateGroup group(v, "search");
  v.scalar("pass", pass_);
  v.array("records", records_);
  for (int side = 0; side < 2; ++side) {
    StateGroup g(v, side == 0 ? "side A" : "side B");
    grid_[side].visit_state(v);
    v.array("grid segments", side_segs_[side]);
  }
  v.array("margins", margin_);
  v.scalar("allowance", allowance_);
  v.scalar("bucket edge", cell_);
  v.scalar("new-contact depth cap", new_depth_cap_);
  v.scalar("list allowance", list_allowance_);
  v.array("candidate starts", cand_start_);
  v.array("candidates", cand_);
  v.array("positions at sort", x_sort_);
  v.scalar("cycles since sort", cycles_since_sort_);
  v.scalar("sorts", sorts_);
  // node_normals_: recomputed wherever read; sized here for a reader whose set changed size.
  v.array("node normals", node_normals_);
}

}  // namespace plyimpact::contact
