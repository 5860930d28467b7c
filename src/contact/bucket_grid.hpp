// Bucket sort for contact search (LS-DYNA Theory Manual, "Bucket sorting"): the bounding box of the
// contact segments is split into cubic buckets of the caller's edge (penalty contact: the median
// segment size; LS-DYNA uses the largest, which puts a graded mesh's whole fine zone in one
// bucket); each segment is listed in every bucket its box (expanded by its search margin)
// overlaps, so a node needs to look in one bucket only. Buckets are a dense CSR array; a rebuild reuses the storage
// (no allocation once the sizes have settled). Cost: O(segments + buckets), buckets capped at
// ~2 per segment by enlarging the edge, so the search is linear in the surface size.
#pragma once

#include <span>
#include <vector>

#include "core/state_visitor.hpp"
#include "core/types.hpp"

namespace plyimpact::contact {

class BucketGrid {
 public:
  // boxes: (num_items, 6) lo_x lo_y lo_z hi_x hi_y hi_z, already expanded by the search margin.
  // cell_hint: requested bucket edge (m), enlarged when the grid would have too many buckets.
  // keep: (num_items) 0 = leave the item out of the buckets (empty: list every item). The grid's
  // extent and buckets come from all boxes, so the items kept are listed exactly as without it.
  void build(std::span<const double> boxes, double cell_hint, std::span<const unsigned char> keep = {});

  // Items whose expanded box overlaps the bucket containing p; empty outside the grid.
  std::span<const Index> candidates(const double* p) const;

  double cell() const { return cell_; }
  std::size_t num_buckets() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }

  // The grid as built (a restart reads it back instead of rebuilding it from boxes it no longer has).
  void visit_state(StateVisitor& visitor);

 private:
  long bucket_of(double x, int d) const;
  // The grid's origin, bucket edge and dimensions from the boxes' extent and the requested edge.
  void size_grid(std::span<const double> boxes, double cell_hint, int threads);
  // offsets_ and items_: every item in each bucket its box overlaps, in item order.
  void list_items(std::span<const double> boxes, std::span<const unsigned char> keep, int threads);
  double lo_[3] = {0, 0, 0};
  double cell_ = 1;
  long dims_[3] = {0, 0, 0};
  std::vector<Index> offsets_;  // (num_buckets + 1)
  std::vector<Index> items_;
  std::vector<Index> fill_;     // scratch: per thread and bucket, counts then positions
  // Below this many items the grid is built on one thread (a parallel region costs a few us).
  static constexpr std::size_t kParallelMinItems = 2048;
};

}  // namespace plyimpact::contact
