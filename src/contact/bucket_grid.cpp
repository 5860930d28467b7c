#include "contact/bucket_grid.hpp"

#include <algorithm>
#include <cmath>

namespace plyimpact::contact {

long BucketGrid::bucket_of(double x, int d) const {
  return std::clamp(long(std::floor((x - lo_[d]) / cell_)), 0L, dims_[d] - 1);
}

void BucketGrid::build(std::span<const double> boxes, double cell_hint) {
  const std::size_t n = boxes.size() / 6;
  double hi[3] = {-1e300, -1e300, -1e300};
  for (int d = 0; d < 3; ++d) lo_[d] = 1e300;
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      lo_[d] = std::min(lo_[d], boxes[6 * i + d]);
      hi[d] = std::max(hi[d], boxes[6 * i + 3 + d]);
    }
  if (n == 0) {
    offsets_.assign(1, 0);
    dims_[0] = dims_[1] = dims_[2] = 0;
    return;
  }
  cell_ = cell_hint > 0 ? cell_hint : 1.0;
  const double max_buckets = 2.0 * double(n) + 64.0;
  for (;;) {
    double count = 1;
    for (int d = 0; d < 3; ++d) count *= std::max(1.0, std::ceil((hi[d] - lo_[d]) / cell_));
    if (count <= max_buckets) break;
    cell_ *= std::cbrt(count / max_buckets) * 1.01;
  }
  for (int d = 0; d < 3; ++d) dims_[d] = std::max(1L, long(std::ceil((hi[d] - lo_[d]) / cell_)));
  const std::size_t nb = std::size_t(dims_[0] * dims_[1] * dims_[2]);
  offsets_.assign(nb + 1, 0);
  auto for_buckets = [&](std::size_t i, auto&& fn) {
    long b0[3], b1[3];
    for (int d = 0; d < 3; ++d) {
      b0[d] = bucket_of(boxes[6 * i + d], d);
      b1[d] = bucket_of(boxes[6 * i + 3 + d], d);
    }
    for (long k = b0[2]; k <= b1[2]; ++k)
      for (long j = b0[1]; j <= b1[1]; ++j)
        for (long l = b0[0]; l <= b1[0]; ++l) fn(std::size_t((k * dims_[1] + j) * dims_[0] + l));
  };
  for (std::size_t i = 0; i < n; ++i) for_buckets(i, [&](std::size_t b) { ++offsets_[b + 1]; });
  for (std::size_t b = 0; b < nb; ++b) offsets_[b + 1] += offsets_[b];
  items_.resize(std::size_t(offsets_[nb]));
  fill_.assign(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) for_buckets(i, [&](std::size_t b) { items_[std::size_t(fill_[b]++)] = Index(i); });
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
