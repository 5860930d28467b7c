#include "model/erosion_neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "model/model.hpp"

namespace plyimpact::model {

namespace {

std::vector<double> centroids(const ElementBlock& block, const std::vector<double>& X) {
  std::vector<double> c(3 * block.size(), 0.0);
  for (std::size_t e = 0; e < block.size(); ++e)
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) c[3 * e + d] += 0.125 * X[3 * std::size_t(block.conn[8 * e + k]) + d];
  return c;
}

// Cell of a point on a grid of spacing `cell`, packed into one key (21 bits per axis, offset so
// that negative cells pack too: plenty for a block's extent over its reference length).
std::int64_t cell_key(long i, long j, long k) {
  constexpr long kOffset = 1L << 20;
  return ((i + kOffset) << 42) | ((j + kOffset) << 21) | (k + kOffset);
}

}  // namespace

double bell_weight(double r, double radius) {
  if (!(r < radius * (1 - 1e-9))) return 0.0;  // at the radius to round-off: outside
  const double q = 1.0 - (r * r) / (radius * radius);
  return q * q;
}

double ErosionNeighbours::mean_count() const {
  const std::size_t n = elements_with_neighbours();
  return n == 0 ? 0.0 : double(index.size()) / double(n);
}

std::size_t ErosionNeighbours::elements_with_neighbours() const {
  std::size_t n = 0;
  for (std::size_t e = 0; e + 1 < start.size(); ++e) n += start[e + 1] > start[e] ? 1 : 0;
  return n;
}

ErosionNeighbours build_erosion_neighbours(const ElementBlock& block, const std::vector<double>& X, double radius,
                                           const std::vector<bool>& needs) {
  ErosionNeighbours out;
  if (std::none_of(needs.begin(), needs.end(), [](bool b) { return b; })) return out;
  const std::vector<double> c = centroids(block, X);
  const auto cell = [&](double v) { return long(std::floor(v / radius)); };
  std::unordered_map<std::int64_t, std::vector<Index>> grid;
  for (std::size_t e = 0; e < block.size(); ++e)
    grid[cell_key(cell(c[3 * e]), cell(c[3 * e + 1]), cell(c[3 * e + 2]))].push_back(Index(e));
  out.start.assign(block.size() + 1, 0);
  out.self_weight.assign(block.size(), 1.0);
  std::vector<std::pair<Index, double>> found;
  for (std::size_t e = 0; e < block.size(); ++e) {
    out.start[e] = Index(out.index.size());
    if (!needs[e]) continue;
    found.clear();
    const long ci = cell(c[3 * e]), cj = cell(c[3 * e + 1]), ck = cell(c[3 * e + 2]);
    for (long i = ci - 1; i <= ci + 1; ++i)
      for (long j = cj - 1; j <= cj + 1; ++j)
        for (long k = ck - 1; k <= ck + 1; ++k) {
          const auto it = grid.find(cell_key(i, j, k));
          if (it == grid.end()) continue;
          for (Index n : it->second) {
            if (std::size_t(n) == e) continue;
            const double dx = c[3 * std::size_t(n)] - c[3 * e], dy = c[3 * std::size_t(n) + 1] - c[3 * e + 1],
                         dz = c[3 * std::size_t(n) + 2] - c[3 * e + 2];
            const double w = bell_weight(std::sqrt(dx * dx + dy * dy + dz * dz), radius) * block.volume0[std::size_t(n)];
            if (w > 0) found.emplace_back(n, w);
          }
        }
    std::sort(found.begin(), found.end());  // ascending index: the sum's order is the model's
    double total = block.volume0[e];
    for (const auto& [n, w] : found) total += w;
    out.self_weight[e] = block.volume0[e] / total;
    for (const auto& [n, w] : found) out.index.push_back(n), out.weight.push_back(w / total);
  }
  out.start[block.size()] = Index(out.index.size());
  return out;
}

}  // namespace plyimpact::model
