// The contact bucket grid (contact/bucket_grid): every item whose box holds a point is among the
// point's candidates, the candidates come in item order, and the grid is the same whatever the
// thread count (its build splits the items into fixed ranges per thread). Reference: a brute-force
// scan of the boxes; the thread counts compared exactly.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/bucket_grid.hpp"

namespace plyimpact {
namespace {

// Boxes of a 60 x 60 grid of 1 mm faces, each expanded by 0.3 mm, on a gently curved sheet: more
// items than the grid's serial threshold, boxes overlapping several buckets.
std::vector<double> sheet_boxes() {
  std::vector<double> boxes;
  for (int j = 0; j < 60; ++j)
    for (int i = 0; i < 60; ++i) {
      const double x = 1e-3 * i, y = 1e-3 * j, z = 2e-3 * std::sin(30.0 * x) * std::cos(20.0 * y);
      const double m = 0.3e-3;
      boxes.insert(boxes.end(), {x - m, y - m, z - 0.2e-3 - m, x + 1e-3 + m, y + 1e-3 + m, z + 0.2e-3 + m});
    }
  return boxes;
}

std::vector<std::vector<Index>> probe(const contact::BucketGrid& grid, const std::vector<double>& points) {
  std::vector<std::vector<Index>> out;
  for (std::size_t p = 0; p < points.size(); p += 3) {
    const auto c = grid.candidates(&points[p]);
    out.emplace_back(c.begin(), c.end());
  }
  return out;
}

TEST(BucketGrid, CandidatesAreCompleteOrderedAndIndependentOfThreads) {
  const std::vector<double> boxes = sheet_boxes();
  ASSERT_GT(boxes.size() / 6, 2048u) << "enough items for the threaded build";
  std::vector<double> points;
  for (int k = 0; k < 400; ++k) {  // deterministic probes over the sheet and around it
    const double x = 61e-3 * std::fmod(0.618034 * k, 1.0), y = 61e-3 * std::fmod(0.414214 * k, 1.0);
    points.insert(points.end(), {x, y, 2e-3 * std::sin(30.0 * x) * std::cos(20.0 * y) + 1e-4 * (k % 5 - 2)});
  }
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(1);
  contact::BucketGrid one;
  one.build(boxes, 1e-3);
  omp_set_num_threads(2);
  contact::BucketGrid two;
  two.build(boxes, 1e-3);
  omp_set_num_threads(threads_before);

  const auto a = probe(one, points), b = probe(two, points);
  EXPECT_EQ(a, b);
  std::size_t found = 0;
  for (std::size_t p = 0; p < a.size(); ++p) {
    EXPECT_TRUE(std::is_sorted(a[p].begin(), a[p].end()));
    const double* q = &points[3 * p];
    for (std::size_t i = 0; i < boxes.size() / 6; ++i) {
      const double* bx = &boxes[6 * i];
      const bool inside = q[0] >= bx[0] && q[0] <= bx[3] && q[1] >= bx[1] && q[1] <= bx[4] && q[2] >= bx[2] && q[2] <= bx[5];
      if (!inside) continue;
      ++found;
      EXPECT_TRUE(std::binary_search(a[p].begin(), a[p].end(), Index(i))) << "probe " << p << " item " << i;
    }
  }
  EXPECT_GT(found, 300u) << "the probes should fall inside boxes";
}

}  // namespace
}  // namespace plyimpact
