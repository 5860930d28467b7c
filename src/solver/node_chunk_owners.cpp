#include "solver/node_chunk_owners.hpp"

#include <algorithm>

#include "solver/rigid_body.hpp"

namespace plyimpact::solver {

NodeChunkOwners::NodeChunkOwners(const model::Model& model, std::size_t chunk_nodes)
    : model_(model), chunk_nodes_(chunk_nodes) {}

const std::vector<std::vector<long>>& NodeChunkOwners::for_bounds(std::span<const long> bounds) {
  const std::size_t nt = bounds.size() - 1;
  if (tables_.size() <= nt) {
    tables_.resize(nt + 1);
    bounds_.resize(nt + 1);
  }
  if (tables_[nt].empty() || !std::equal(bounds.begin(), bounds.end(), bounds_[nt].begin(), bounds_[nt].end())) {
    tables_[nt] = build(bounds);
    bounds_[nt].assign(bounds.begin(), bounds.end());
  }
  return tables_[nt];
}

const std::vector<std::vector<long>>& NodeChunkOwners::for_threads(int nt) {
  const long num_chunks = long(model_.schedule.chunks.size());
  even_.resize(std::size_t(nt) + 1);
  for (int t = 0; t <= nt; ++t) even_[std::size_t(t)] = t < nt ? thread_range(num_chunks, t, nt).begin : num_chunks;
  return for_bounds(even_);
}

NodeChunkOwners::Table NodeChunkOwners::build(std::span<const long> bounds) const {
  const int nt = int(bounds.size()) - 1;
  const std::size_t n = model_.num_nodes();
  const std::size_t num_node_chunks = (n + chunk_nodes_ - 1) / chunk_nodes_;
  // votes[chunk * nt + t]: element-node incidences of thread t's element chunks in this node chunk.
  std::vector<std::size_t> votes(num_node_chunks * std::size_t(nt), 0);
  const auto& schedule = model_.schedule;
  for (int t = 0; t < nt; ++t) {
    for (long c = bounds[std::size_t(t)]; c < bounds[std::size_t(t) + 1]; ++c) {
      const auto& chunk = schedule.chunks[std::size_t(c)];
      const auto& conn = model_.blocks[std::size_t(chunk.block)].conn;
      for (std::size_t k = 8 * std::size_t(chunk.begin); k < 8 * std::size_t(chunk.end); ++k)
        ++votes[std::size_t(conn[k]) / chunk_nodes_ * std::size_t(nt) + std::size_t(t)];
    }
  }
  for (const auto& body : model_.rigid_bodies) {
    const long count = long(body.nodes.size());
    const int placing = RigidBodies::placing_threads(count, nt > 1, nt);
    for (int t = 0; t < placing; ++t) {
      const ThreadRange range = thread_range(count, t, placing);
      for (long k = range.begin; k < range.end; ++k)
        ++votes[std::size_t(body.nodes[std::size_t(k)]) / chunk_nodes_ * std::size_t(nt) + std::size_t(t)];
    }
  }
  Table chunks(static_cast<std::size_t>(nt));
  for (std::size_t c = 0; c < num_node_chunks; ++c) {
    const auto first = votes.begin() + std::ptrdiff_t(c * std::size_t(nt));
    const auto owner = std::max_element(first, first + nt) - first;  // ties and no votes: the lowest thread
    chunks[std::size_t(owner)].push_back(long(c));
  }
  return chunks;
}

}  // namespace plyimpact::solver
