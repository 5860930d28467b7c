// Nodes that erosion leaves with nothing acting on them (Solver::remove_freed_nodes in solver.hpp
// says what "removed" means and why).
#include <algorithm>

#include "solver/solver.hpp"

namespace plyimpact::solver {

void Solver::build_node_adjacency() {
  if (!node_elements_.empty()) return;
  const std::size_t n = model_.num_nodes();
  node_elements_start_.assign(n + 1, 0);
  for (const auto& blk : model_.blocks)
    for (Index node : blk.conn) ++node_elements_start_[node + 1];
  for (std::size_t i = 0; i < n; ++i) node_elements_start_[i + 1] += node_elements_start_[i];
  node_elements_.resize(node_elements_start_[n]);
  std::vector<Index> fill(node_elements_start_.begin(), node_elements_start_.end() - 1);
  for (std::size_t b = 0; b < model_.blocks.size(); ++b)
    for (std::size_t e = 0; e < model_.blocks[b].size(); ++e)
      for (int k = 0; k < 8; ++k) node_elements_[fill[model_.blocks[b].conn[8 * e + k]]++] = {int(b), Index(e)};
}

void Solver::remove_freed_nodes(const std::vector<std::pair<int, Index>>& deleted) {
  // Before the contributors exist (an erosion at the initial evaluation) nobody could say which
  // nodes a contact or an interface holds: such nodes stay.
  if (!contributors_built_ || deleted.empty()) return;
  build_node_adjacency();
  const auto held_by_element = [&](Index node) {
    for (Index p = node_elements_start_[node]; p < node_elements_start_[node + 1]; ++p) {
      const auto [b, e] = node_elements_[p];
      if (model_.blocks[std::size_t(b)].rigid) continue;
      const auto& mask = alive_[std::size_t(b)];
      if (mask.empty() || mask[std::size_t(e)]) return true;
    }
    return false;
  };
  const auto constrained = [&](Index node) {
    for (int d = 0; d < 3; ++d)
      if (dof_constraint_[3 * std::size_t(node) + d] >= 0) return true;
    return false;
  };
  std::vector<Index> candidates;
  for (const auto& [b, e] : deleted)
    for (int k = 0; k < 8; ++k) candidates.push_back(model_.blocks[std::size_t(b)].conn[8 * std::size_t(e) + k]);
  std::sort(candidates.begin(), candidates.end());  // node order: the energy sum is deterministic
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  State& s = state_;
  const auto removed = [&](Index node) { return !s.removed_nodes.empty() && s.removed_nodes[std::size_t(node)]; };
  std::erase_if(candidates, [&](Index node) {
    return removed(node) || node_body_[std::size_t(node)] >= 0 || constrained(node) || held_by_element(node);
  });
  if (candidates.empty()) return;
  held_scratch_.assign(model_.num_nodes(), 0);
  for (const auto& c : contributors_) c->mark_held_nodes(held_scratch_);
  for (Index node : candidates) {
    const std::size_t i = std::size_t(node);
    if (held_scratch_[i]) continue;
    if (s.removed_nodes.empty()) s.removed_nodes.assign(model_.num_nodes(), 0);
    // Nothing acted on the node in this pass (its last element was deleted before it applied its
    // force), so the kinetic energy the next balance would give it is exactly this.
    double ke = 0;
    for (int d = 0; d < 3; ++d) {
      const double v = s.v[3 * i + std::size_t(d)];
      ke += 0.5 * node_mass_[i] * v * v;
      s.v[3 * i + std::size_t(d)] = 0.0;
    }
    s.eroded_kinetic_energy += ke;
    s.removed_nodes[i] = 1;
    inverse_mass_[i] = 0.0;
  }
}

void Solver::apply_removed_nodes() {
  for (std::size_t i = 0; i < state_.removed_nodes.size(); ++i)
    if (state_.removed_nodes[i]) inverse_mass_[i] = 0.0;
}

}  // namespace plyimpact::solver
