// Which thread updates which chunk of nodes in the node update. A node's force is scattered by the
// thread that computes its elements (the element pass gives thread t a contiguous range of element
// chunks, ChunkPlan::bounds); if another thread then reads that force and writes the velocity
// and position, every cache line of f, v and x crosses between cores twice per cycle, which can
// make the node update slower on two threads than on one. So each node chunk goes to
// the thread whose element chunks touch most of its nodes, and a rigid body's nodes to the
// thread that places them (RigidBodies::placing_threads). The kinetic energy is still
// summed per chunk and then in chunk order, so the results do not depend on the thread count.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"
#include "solver/thread_range.hpp"

namespace plyimpact::solver {

class NodeChunkOwners {
 public:
  // chunk_nodes: nodes per node chunk.
  NodeChunkOwners(const model::Model& model, std::size_t chunk_nodes);

  // Per thread, the node chunks it updates, in increasing order, when thread t of nt computes the
  // element chunks [bounds[t], bounds[t + 1]) (nt = bounds.size() - 1). One table is kept per thread
  // count and rebuilt only when its bounds change, so a run that switches thread counts allocates
  // nothing until the element pass is split anew. Call outside the parallel region.
  const std::vector<std::vector<long>>& for_bounds(std::span<const long> bounds);
  // The same for nt even ranges of element chunks (thread_range).
  const std::vector<std::vector<long>>& for_threads(int nt);

 private:
  using Table = std::vector<std::vector<long>>;  // (nt) node chunks per thread
  Table build(std::span<const long> bounds) const;

  const model::Model& model_;
  std::size_t chunk_nodes_;
  std::vector<Table> tables_;               // index nt: the table for nt threads (empty until used)
  std::vector<std::vector<long>> bounds_;   // index nt: the element chunk bounds of tables_[nt]
  std::vector<long> even_;                  // scratch of for_threads
};

}  // namespace plyimpact::solver
