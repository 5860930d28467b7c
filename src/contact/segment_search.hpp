// Node-to-segment search over a segment set (docs/theory.md section 10): bucket sort of each side's
// segments (contact/bucket_grid), re-sorted every BSORT cycles or when a force node has moved a
// quarter of the list allowance; per contact node a candidate list (the segments it can reach
// before the next sort, in bucket order); per segment a hot record refreshed at most once per pass
// (bilinear coefficients, bounding sphere, normal and in-plane bounds) and the closest-point
// projection (contact/geometry) onto it.
//   Allowance and bucket edge follow the median segment size and each segment's box is expanded by
//   its own margin (release depth + 5 % of its extent + allowance), so a graded mesh's fine zone is
//   not one bucket.
// Which segment a node is in contact with is the law's business: the penalty contact's catch rules
// are in contact/catch_rules; a tie (tiebreak, bonded interface) asks `nearest_segment`. Both walk
// `candidates(i)` and read `record(...)`. The set is passed to each call (not stored), so the owner
// of set and search can be moved.
// A tie over its own segment set (tests/contact/test_segment_search.cpp):
//   SegmentSet set(model, spec, x);  SegmentSearch search(options);
//   search.reset(set, x);  search.sort(set, x, 0.0, /*full_depth=*/true);
//   per node i: s = search.nearest_segment(set, i, x, distance, projection)  -> its partner (s, xi, eta)
//   after erosion: remap = set.rebuild(alive, x), partner s -> remap.segment[s], then reset + sort.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <vector>

#include "contact/bucket_grid.hpp"
#include "contact/geometry.hpp"
#include "contact/segment_set.hpp"
#include "core/aligned_allocator.hpp"
#include "core/state_visitor.hpp"

namespace plyimpact::contact {

struct SearchOptions {
  double MAXPAR = 1.025;  // parametric tolerance of the projection
  // Bucket sort at least every BSORT cycles; 0 (LS-DYNA's blank: the code picks the interval):
  // only when the motion requires it (sort_due). The lists hold every segment within reach either
  // way, so BSORT changes what a pass costs, never what it finds.
  int BSORT = 0;
};

// What a pass needs to know of the force nodes' motion (begin_pass).
struct PassMotion {
  double v_max2 = 0;   // largest |v|^2 of a force node, (m/s)^2
  double moved2 = 0;   // largest |x - x_sort|^2 since the last sort, m^2
};

class SegmentSearch {
 public:
  // Hot per-segment record, one 128-byte record per segment aligned to 128 bytes (a candidate's
  // tests read it contiguously instead of gathering four nodes; the sphere test reads only its
  // first cache line): [0..2] centre c, [3] bounding radius (float, rounded up) and refresh stamp,
  // [4..6] a1, [7] release depth, [8..10] a2, [11] two floats: bound of the unit normal's deviation
  // from the centre normal and 1 / |a1 x a2|, [12..14] a3 (geometry.hpp coefficient form), [15] two
  // floats: in-plane bounds of (p - c) . a1 and (p - c) . a2 for an accepted node (refresh_segment).
  static constexpr std::size_t kRecord = 16;

  SegmentSearch() = default;
  explicit SegmentSearch(SearchOptions options) : options_(options) {}

  // After the set was (re)assembled at x: margins, allowance, bucket edge, records (all stale).
  // The caller sorts next.
  void reset(const SegmentSet& set, const double* x);

  // Start of a pass: every record and node normal becomes stale; returns the force nodes' motion.
  PassMotion begin_pass(const SegmentSet& set, const double* x, const double* v);
  // Re-sort due: at the interval, when a node has moved a quarter of the list allowance since the
  // last sort, or when the new-contact depth of this pass (4 dt v_max) exceeds the lists' cap.
  bool sort_due(const PassMotion& motion, double step_depth) const {
    const double lim2 = 0.25 * list_allowance_ * 0.25 * list_allowance_;
    const bool interval = options_.BSORT > 0 && cycles_since_sort_ >= options_.BSORT;
    return interval || motion.moved2 > lim2 || step_depth > new_depth_cap_;
  }
  // Bucket sort at x, refresh of the records the lists may reach, candidate lists. step_depth: the
  // largest new-contact depth of the present pass, which bounds the lists' depth cap; full_depth:
  // lists for any depth (initial-penetration check, the pass after a rebuild).
  void sort(const SegmentSet& set, const double* x, double step_depth, bool full_depth);
  // Candidate lists at x from the present grids (sort).
  void build_candidates(const SegmentSet& set, const double* x, bool full_depth);
  // Every record and node normal at x.
  void refresh_all(const SegmentSet& set, const double* x);

  // Segments contact node i may meet until the next sort.
  std::span<const Index> candidates(std::size_t i) const {
    return {cand_.data() + cand_start_[i], std::size_t(cand_start_[i + 1] - cand_start_[i])};
  }
  // Record of segment s, refreshed at x if stale in this pass. Safe to call from several threads
  // within a pass: the first to find the record stale claims it through its stamp and refreshes
  // it; the others wait for the stamp (a refresh is a deterministic function of x, so who does it
  // does not change the result).
  const double* record(const SegmentSet& set, std::size_t s, const double* x) {
    double* g = &records_[kRecord * s];
    if (__atomic_load_n(stamp_word(g), __ATOMIC_ACQUIRE) != pass_) refresh_claimed(set, s, x);
    return g;
  }
  // Area-weighted outward normal of contact node i's own surface (8 a1 x a2 summed over its own
  // segments, ascending), computed at x.
  const double* node_normal(const SegmentSet& set, std::size_t i, const double* x);

  static float radius(const double* g) {
    float r;
    std::memcpy(&r, g + 3, sizeof r);
    return r;
  }
  static std::uint32_t stamp(const double* g) {
    std::uint32_t s;
    std::memcpy(&s, reinterpret_cast<const char*>(g + 3) + sizeof(float), sizeof s);
    return s;
  }

  // Closest segment of the other side (or, single surface, any other) onto which contact node i
  // projects (within MAXPAR) at |gap| <= max_distance (at most the segment's release depth), and
  // its projection; -1 if none. Ties: the first met in the candidate list. For ties and interfaces:
  // no orientation or catch rules. The candidate lists must be built with full_depth.
  long nearest_segment(const SegmentSet& set, std::size_t i, const double* x, double max_distance, Projection& best);

  const SearchOptions& options() const { return options_; }
  // Bound of the new-contact depth until the next sort, m.
  double new_depth_cap() const { return new_depth_cap_; }
  long sorts() const { return sorts_; }

  // Counters, the positions and lists of the last sort, the grids and the records (the node
  // normals are recomputed wherever they are read; they are visited for their size only).
  void visit_state(StateVisitor& visitor);

 private:
  // The stamp as a word for the atomic builtins (it shares slot 3 with the radius).
  using StampWord = std::uint32_t __attribute__((may_alias));
  static StampWord* stamp_word(double* g) { return reinterpret_cast<StampWord*>(reinterpret_cast<char*>(g + 3) + sizeof(float)); }
  // Stamp of a record being refreshed by another thread (pass_ never reaches it).
  static constexpr std::uint32_t kRefreshing = 0xFFFFFFFFu;
  // Refreshes the record (stamp written last, with release); only one thread per record at a time.
  void refresh_segment(const SegmentSet& set, std::size_t s, const double* x);
  // record()'s slow path: claim the stale record and refresh it, or wait for the thread that did.
  void refresh_claimed(const SegmentSet& set, std::size_t s, const double* x);
  // Parts of sort (segment_search.cpp): the querying nodes' boxes per side; one side's segment
  // boxes and which can be in a list (keep_); the records of those.
  void querying_node_boxes(const SegmentSet& set, const double* x, double (&box)[2][6]) const;
  void segment_boxes(const SegmentSet& set, int side, const double* x, const double (&nodes)[6]);
  void refresh_listed(const SegmentSet& set, const double* x);

  SearchOptions options_;
  AlignedVector<double, 128> records_;  // (S, kRecord)
  std::vector<double> node_normals_;    // (N, 3) scratch of node_normal
  std::uint32_t pass_ = 1;  // a record is fresh when its stamp equals it (starts at 1: zeroed records are stale)
  BucketGrid grid_[2];                  // per side (single surface: [0] only)
  std::vector<Index> side_segs_[2];     // grid item -> segment
  std::vector<double> boxes_[2];        // scratch of sort
  std::vector<unsigned char> keep_[2];  // scratch of sort: grid item can be in a list (segment_boxes)
  std::vector<double> margin_;          // (S) search margin of each segment's box, m
  double allowance_ = 0, cell_ = 0;     // bucket allowance (a sixteenth of the median extent), bucket edge
  double new_depth_cap_ = 0;            // bound of the new-contact depth until the next sort, m
  double list_allowance_ = 0;           // motion allowed before the next sort (<= allowance_), m
  std::vector<Index> cand_start_, cand_;  // (CSR over contact nodes) candidate segments
  static constexpr std::size_t kListChunk = 512;  // contact nodes per chunk of build_candidates
  std::vector<std::vector<Index>> chunk_cand_;    // scratch of build_candidates, one list per chunk
  std::vector<double> x_sort_;          // (U, 3) force node positions at the last sort
  long cycles_since_sort_ = 0, sorts_ = 0;
};

}  // namespace plyimpact::contact
