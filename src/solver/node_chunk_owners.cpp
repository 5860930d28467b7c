#include "solver/node_chunk_owners.hpp"

#include <algorithm>

#include "solver/rigid_body.hpp"

namespace plyimpact::solver {

NodeChunkOwners::NodeChunkOwners(const model::Model& model, std::size_t chunk_nodes)
    : model_(model), chunk_nodes_(chunk_nodes) {}

const std::vector<std::vector<long>>& NodeChunkOwners::for_threads(int nt) {
  if (tables_.size() <= std::size_t(nt)) tables_.resize(std::size_t(nt) + 1);
  Table& table = tables_[std::size_t(nt)];
  if (table.empty()) table = build(nt);
  return table;
}

NodeChunkOwners::Table NodeChunkOwners::build(int nt) const {
  const std::size_t n = model_.num_nodes();
  const std::size_t num_node_chunks = (n + chunk_nodes_ - 1) / chunk_nodes_;
  // votes[chunk * nt + t]: element-node incidences of thread t's element chunks in this node chunk.
  std::vector<std::size_t> votes(num_node_chunks * std::size_t(nt), 0);
  const auto& schedule = model_.schedule;
  const int num_chunks = int(schedule.chunks.size());
  for (int t = 0; t < nt; ++t) {
    const ThreadRange range = thread_range(num_chunks, t, nt);
    for (long c = range.begin; c < range.end; ++c) {
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
