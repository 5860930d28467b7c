// Which thread runs which element chunks, and in which order, in the parallel element pass.
//
// The results do not depend on the plan: chunks of one colour share no node, and a chunk waits for
// every chunk of lower colour that shares a node with it (its predecessors), so each node receives
// its forces in colour order whichever thread computes them. The plan decides the wall time only.
// Each thread gets a contiguous range of chunks (its part of the mesh, whose nodes the node update
// keeps on the same core: NodeChunkOwners) of about equal measured cost, and runs them in the order
// that a simulation of the pass with those costs finds: a thread starts, among its chunks whose
// predecessors are done, the one that can start first, ties going to the longest chain of work
// behind it. That puts first the chunks another thread waits for. In a laminate two plies of one
// angle meshed as one (no interface between them) share nodes; where the range boundary falls between
// them, running each thread's chunks colour by colour puts the lower ply's chunks last on one thread
// while the other waits for them before it can run the upper ply's.
//   No deadlock whatever the costs: every thread follows one global order (the simulated start
// times), which lists each chunk after its predecessors, so the earliest unfinished chunk of that
// order can always run.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"

namespace plyimpact::solver {

class ChunkPlan {
 public:
  explicit ChunkPlan(const model::Model& model);

  std::size_t num_chunks() const { return preds_start_.size() - 1; }
  // The chunks of lower colour that share a node with chunk c, ascending.
  std::span<const int> predecessors(int c) const {
    return {preds_.data() + preds_start_[std::size_t(c)],
            std::size_t(preds_start_[std::size_t(c) + 1] - preds_start_[std::size_t(c)])};
  }

  // A plan for nt threads from per-chunk costs (any unit; a chunk of cost 0 counts as the smallest
  // positive one). With a plan for nt in place, it is replaced only when the simulation gives the new
  // one a span shorter by at least the share min_gain (each new split moves nodes between the
  // threads' caches); returns whether the plan changed. Allocates only on first use.
  bool plan(int nt, std::span<const double> cost, double min_gain = 0);
  // The wall time the simulation gives the current plan with these costs (their unit).
  double simulated_span(std::span<const double> cost);
  // The first plan of a model: costs from the element counts, eight per fully integrated element.
  std::vector<double> element_count_costs() const;

  int threads() const { return threads_; }
  // Thread t's chunks in the order it runs them.
  std::span<const int> order(int t) const {
    return {order_.data() + order_start_[std::size_t(t)],
            std::size_t(order_start_[std::size_t(t) + 1] - order_start_[std::size_t(t)])};
  }
  // Thread t runs the chunks [bounds[t], bounds[t + 1]).
  std::span<const long> bounds() const { return bounds_; }

 private:
  // Simulates the pass with these bounds and the costs of rank_chains; fills owner_ and start_ and
  // returns the span.
  double simulate(std::span<const long> bounds);
  // The per-thread orders from start_ (the bounds' threads).
  void take_order(std::span<const long> bounds);
  // cost_ (zero costs raised to the smallest positive one) and rank_: each chunk's cost plus the
  // costliest chain of successors after it.
  void rank_chains(std::span<const double> cost);

  const model::Model& model_;
  std::vector<Index> preds_start_, succs_start_;  // CSR
  std::vector<int> preds_, succs_;
  std::vector<int> topological_;  // colour by colour: predecessors first
  int threads_ = 0;
  std::vector<long> bounds_;
  std::vector<Index> order_start_;
  std::vector<int> order_;
  // Simulation scratch.
  std::vector<double> cost_, rank_, start_, ready_, thread_free_;
  std::vector<int> waiting_preds_, owner_;
  std::vector<std::vector<int>> candidates_;  // per thread: chunks whose predecessors are placed
  std::vector<long> trial_, best_;
};

}  // namespace plyimpact::solver
