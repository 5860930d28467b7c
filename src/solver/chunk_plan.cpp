#include "solver/chunk_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plyimpact::solver {
namespace {

// Shifts of each range boundary, in chunks, that the plan tries beyond the equal-cost split: the
// cost of a range is not its wall time when its chunks wait for another thread's.
constexpr long kBoundaryShifts = 4;

}  // namespace

ChunkPlan::ChunkPlan(const model::Model& model) : model_(model) {
  const auto& schedule = model.schedule;
  const std::size_t num_chunks = schedule.chunks.size();
  std::vector<int> color(num_chunks, 0);
  for (std::size_t k = 0; k < schedule.colors.size(); ++k)
    for (int c : schedule.colors[k]) {
      color[std::size_t(c)] = int(k);
      topological_.push_back(c);
    }
  std::vector<std::vector<int>> node_chunks(model.num_nodes());
  for (std::size_t c = 0; c < num_chunks; ++c) {
    const auto& ch = schedule.chunks[c];
    const auto& conn = model.blocks[std::size_t(ch.block)].conn;
    for (Index e = ch.begin; e < ch.end; ++e)
      for (int k = 0; k < 8; ++k) {
        auto& list = node_chunks[std::size_t(conn[8 * std::size_t(e) + std::size_t(k)])];
        if (list.empty() || list.back() != int(c)) list.push_back(int(c));
      }
  }
  std::vector<std::vector<int>> preds(num_chunks), succs(num_chunks);
  for (const auto& list : node_chunks)
    for (int a : list)
      for (int b : list)
        if (color[std::size_t(b)] < color[std::size_t(a)]) preds[std::size_t(a)].push_back(b);
  for (std::size_t c = 0; c < num_chunks; ++c) {
    auto& p = preds[c];
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
    for (int b : p) succs[std::size_t(b)].push_back(int(c));
  }
  auto to_csr = [](const std::vector<std::vector<int>>& lists, std::vector<Index>& start, std::vector<int>& flat) {
    start.assign(lists.size() + 1, 0);
    for (std::size_t c = 0; c < lists.size(); ++c) {
      flat.insert(flat.end(), lists[c].begin(), lists[c].end());
      start[c + 1] = Index(flat.size());
    }
  };
  to_csr(preds, preds_start_, preds_);
  to_csr(succs, succs_start_, succs_);
}

std::vector<double> ChunkPlan::element_count_costs() const {
  std::vector<double> cost;
  for (const auto& ch : model_.schedule.chunks)
    cost.push_back(double(ch.end - ch.begin) * model_.blocks[std::size_t(ch.block)].points());
  return cost;
}

void ChunkPlan::rank_chains(std::span<const double> cost) {
  const std::size_t n = num_chunks();
  cost_.resize(n);
  double smallest = std::numeric_limits<double>::infinity();
  for (double c : cost)
    if (c > 0) smallest = std::min(smallest, c);
  if (!std::isfinite(smallest)) smallest = 1.0;
  for (std::size_t c = 0; c < n; ++c) cost_[c] = cost[c] > 0 ? cost[c] : smallest;
  rank_.assign(n, 0.0);
  for (auto it = topological_.rbegin(); it != topological_.rend(); ++it) {
    const std::size_t c = std::size_t(*it);
    double behind = 0;
    for (Index s = succs_start_[c]; s < succs_start_[c + 1]; ++s) behind = std::max(behind, rank_[std::size_t(succs_[std::size_t(s)])]);
    rank_[c] = cost_[c] + behind;
  }
}

double ChunkPlan::simulate(std::span<const long> bounds) {
  const std::size_t n = num_chunks();
  const int nt = int(bounds.size()) - 1;
  owner_.resize(n);
  for (int t = 0; t < nt; ++t)
    for (long c = bounds[std::size_t(t)]; c < bounds[std::size_t(t) + 1]; ++c) owner_[std::size_t(c)] = t;
  candidates_.resize(std::size_t(nt));
  for (auto& list : candidates_) list.clear();
  thread_free_.assign(std::size_t(nt), 0.0);
  waiting_preds_.resize(n);
  ready_.assign(n, 0.0);
  start_.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    waiting_preds_[c] = int(preds_start_[c + 1] - preds_start_[c]);
    if (waiting_preds_[c] == 0) candidates_[std::size_t(owner_[c])].push_back(int(c));
  }
  double span = 0;
  for (std::size_t placed = 0; placed < n; ++placed) {
    // The (thread, chunk) that can start first; ties: the longer chain behind, then the lower chunk.
    int best_t = -1;
    std::size_t best_k = 0;
    double best_start = 0;
    for (int t = 0; t < nt; ++t) {
      const auto& list = candidates_[std::size_t(t)];
      for (std::size_t k = 0; k < list.size(); ++k) {
        const int c = list[k];
        const double s = std::max(thread_free_[std::size_t(t)], ready_[std::size_t(c)]);
        if (best_t < 0 || s < best_start) {
          best_t = t, best_k = k, best_start = s;
          continue;
        }
        if (s > best_start) continue;
        const int b = candidates_[std::size_t(best_t)][best_k];
        if (rank_[std::size_t(c)] > rank_[std::size_t(b)] || (rank_[std::size_t(c)] == rank_[std::size_t(b)] && c < b))
          best_t = t, best_k = k;
      }
    }
    auto& list = candidates_[std::size_t(best_t)];
    const std::size_t c = std::size_t(list[best_k]);
    list[best_k] = list.back();
    list.pop_back();
    start_[c] = best_start;
    const double finish = best_start + cost_[c];
    thread_free_[std::size_t(best_t)] = finish;
    span = std::max(span, finish);
    for (Index s = succs_start_[c]; s < succs_start_[c + 1]; ++s) {
      const std::size_t next = std::size_t(succs_[std::size_t(s)]);
      ready_[next] = std::max(ready_[next], finish);
      if (--waiting_preds_[next] == 0) candidates_[std::size_t(owner_[next])].push_back(int(next));
    }
  }
  return span;
}

void ChunkPlan::take_order(std::span<const long> bounds) {
  const std::size_t n = num_chunks();
  const int nt = int(bounds.size()) - 1;
  order_.resize(n);
  for (std::size_t c = 0; c < n; ++c) order_[c] = int(c);
  // Each thread's chunks in the order the simulation started them. Costs are positive, so a chunk
  // starts strictly after each of its predecessors: the start times are the one global order that
  // lists every chunk after them. (std::sort: a stable sort would allocate.)
  std::sort(order_.begin(), order_.end(), [&](int a, int b) {
    const std::size_t i = std::size_t(a), j = std::size_t(b);
    if (owner_[i] != owner_[j]) return owner_[i] < owner_[j];
    return start_[i] < start_[j] || (start_[i] == start_[j] && a < b);
  });
  order_start_.assign(std::size_t(nt) + 1, 0);
  for (std::size_t c = 0; c < n; ++c) ++order_start_[std::size_t(owner_[c]) + 1];
  for (int t = 0; t < nt; ++t) order_start_[std::size_t(t) + 1] += order_start_[std::size_t(t)];
}

double ChunkPlan::simulated_span(std::span<const double> cost) {
  rank_chains(cost);
  return simulate(bounds_);
}

bool ChunkPlan::plan(int nt, std::span<const double> cost, double min_gain) {
  const long n = long(num_chunks());
  rank_chains(cost);
  const double current = threads_ == nt ? simulate(bounds_) : std::numeric_limits<double>::infinity();
  // Equal-cost split: boundary t at the first chunk whose prefix reaches t / nt of the total.
  double total = 0;
  for (double c : cost_) total += c;
  trial_.assign(std::size_t(nt) + 1, n);
  trial_[0] = 0;
  double prefix = 0;
  long c = 0;
  for (int t = 1; t < nt; ++t) {
    const double target = total * t / nt;
    while (c < n && prefix + 0.5 * cost_[std::size_t(c)] < target) prefix += cost_[std::size_t(c++)];
    trial_[std::size_t(t)] = std::max(c, trial_[std::size_t(t) - 1]);
  }
  best_.assign(trial_.begin(), trial_.end());
  double best = simulate(best_);
  for (int t = 1; t < nt; ++t)
    for (long shift = -kBoundaryShifts; shift <= kBoundaryShifts; ++shift) {
      if (shift == 0) continue;
      trial_.assign(best_.begin(), best_.end());
      trial_[std::size_t(t)] += shift;
      if (trial_[std::size_t(t)] < trial_[std::size_t(t) - 1] || trial_[std::size_t(t)] > trial_[std::size_t(t) + 1]) continue;
      const double span = simulate(trial_);
      if (span < best) {
        best = span;
        best_.assign(trial_.begin(), trial_.end());
      }
    }
  if (!(best < (1.0 - min_gain) * current)) return false;
  threads_ = nt;
  bounds_.assign(best_.begin(), best_.end());
  simulate(bounds_);
  take_order(bounds_);
  return true;
}

}  // namespace plyimpact::solver
