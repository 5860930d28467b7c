#include "contact/bucket_grid.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace plyimpact::contact {

long BucketGrid::bucket_of(double x, int d) const {
  return std::clamp(long(std::floor((x - lo_[d]) / cell_)), 0L, dims_[d] - 1);
}

void BucketGrid::build(std::span<const double> boxes, double cell_hint, std::span<const unsigned char> keep) {
  const std::size_t n = boxes.size() / 6;
  if (n == 0) {
    offsets_.assign(1, 0);
    dims_[0] = dims_[1] = dims_[2] = 0;
    return;
  }
  const int threads = n >= kParallelMinItems ? omp_get_max_threads() : 1;
  size_grid(boxes, cell_hint, threads);
  list_items(boxes, keep, threads);
}

void BucketGrid::size_grid(std::span<const double> boxes, double cell_hint, int threads) {
  const long n = long(boxes.size() / 6);
  double lo0 = 1e300, lo1 = 1e300, lo2 = 1e300, hi0 = -1e300, hi1 = -1e300, hi2 = -1e300;  // exact in any order
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1) \
    reduction(min : lo0, lo1, lo2) reduction(max : hi0, hi1, hi2)
  for (long i = 0; i < n; ++i) {
    const double* b = &boxes[6 * std::size_t(i)];
    lo0 = std::min(lo0, b[0]), lo1 = std::min(lo1, b[1]), lo2 = std::min(lo2, b[2]);
    hi0 = std::max(hi0, b[3]), hi1 = std::max(hi1, b[4]), hi2 = std::max(hi2, b[5]);
  }
  lo_[0] = lo0, lo_[1] = lo1, lo_[2] = lo2;
  const double hi[3] = {hi0, hi1, hi2};
  cell_ = cell_hint > 0 ? cell_hint : 1.0;
  const double max_buckets = 2.0 * double(n) + 64.0;
  for (;;) {
    double count = 1;
    for (int d = 0; d < 3; ++d) count *= std::max(1.0, std::ceil((hi[d] - lo_[d]) / cell_));
    if (count <= max_buckets) break;
    cell_ *= std::cbrt(count / max_buckets) * 1.01;
  }
  for (int d = 0; d < 3; ++d) dims_[d] = std::max(1L, long(std::ceil((hi[d] - lo_[d]) / cell_)));
}

void BucketGrid::list_items(std::span<const double> boxes, std::span<const unsigned char> keep, int threads) {
  const std::size_t n = boxes.size() / 6, nb = std::size_t(dims_[0] * dims_[1] * dims_[2]);
  auto for_buckets = [&](std::size_t i, auto&& fn) {
    if (!keep.empty() && !keep[i]) return;
    long b0[3], b1[3];
    for (int d = 0; d < 3; ++d) {
      b0[d] = bucket_of(boxes[6 * i + d], d);
      b1[d] = bucket_of(boxes[6 * i + 3 + d], d);
    }
    for (long k = b0[2]; k <= b1[2]; ++k)
      for (long j = b0[1]; j <= b1[1]; ++j)
        for (long l = b0[0]; l <= b1[0]; ++l) fn(std::size_t((k * dims_[1] + j) * dims_[0] + l));
  };
  // Items split into `threads` fixed contiguous ranges; fill_[r * nb + b] counts range r's items in
  // bucket b, then is where the next of them goes. Buckets list range by range, i.e. in item order.
  fill_.assign(std::size_t(threads) * nb, 0);
  offsets_.resize(nb + 1);
  auto range = [&](int r) {
    return std::pair{n * std::size_t(r) / std::size_t(threads), n * std::size_t(r + 1) / std::size_t(threads)};
  };
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    // Range r is counted and filled by the same thread (a team smaller than asked takes several).
    const int t = omp_get_thread_num(), team = omp_get_num_threads();
    for (int r = t; r < threads; r += team) {
      const auto [i0, i1] = range(r);
      Index* count = &fill_[std::size_t(r) * nb];
      for (std::size_t i = i0; i < i1; ++i) for_buckets(i, [&](std::size_t b) { ++count[b]; });
    }
#pragma omp barrier
#pragma omp single
    {
      Index at = 0;
      for (std::size_t b = 0; b < nb; ++b) {
        offsets_[b] = at;
        for (int r = 0; r < threads; ++r) {
          Index& c = fill_[std::size_t(r) * nb + b];
          const Index k = c;
          c = at;
          at += k;
        }
      }
      offsets_[nb] = at;
      items_.resize(std::size_t(at));
    }
    for (int r = t; r < threads; r += team) {
      const auto [i0, i1] = range(r);
      Index* next = &fill_[std::size_t(r) * nb];
      for (std::size_t i = i0; i < i1; ++i) for_buckets(i, [&](std::size_t b) { items_[std::size_t(next[b]++)] = Index(i); });
    }
  }
}

std::span<const Index> BucketGrid::candidates(const double* p) const {
  if (dims_[0] == 0) return {};
  long b[3];
  for (int d = 0; d < 3; ++d) {
    const double f = (p[d] - lo_[d]) / cell_;
    if (f < 0 || f >= double(dims_[d])) return {};
    b[d] = long(f);
  }
  const std::size_t k = std::size_t((b[2] * dims_[1] + b[1]) * dims_[0] + b[0]);
  return {items_.data() + offsets_[k], std::size_t(offsets_[k + 1] - offsets_[k])};
}

void BucketGrid::visit_state(StateVisitor& v) {
  v.scalar("origin", lo_);
  v.scalar("cell", cell_);
  v.scalar("dims", dims_);
  v.array("offsets", offsets_);
  v.array("items", items_);
}

}  // namespace plyimpact::contact
