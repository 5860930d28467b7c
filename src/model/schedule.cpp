#include <algorithm>

#include "model/model.hpp"

namespace plyimpact::model {

Schedule make_schedule(const std::vector<ElementBlock>& blocks, std::size_t num_nodes, Index chunk_size) {
  Schedule s;
  for (int b = 0; b < int(blocks.size()); ++b) {
    if (blocks[b].rigid) continue;  // rigid elements carry no stress: nothing to update
    const Index n = Index(blocks[b].size());
    for (Index begin = 0; begin < n; begin += chunk_size) s.chunks.push_back({b, begin, std::min(n, begin + chunk_size)});
  }
  // Node -> chunks touching it (CSR), then greedy colouring in chunk order.
  std::vector<Index> count(num_nodes + 1, 0);
  std::vector<Index> last(num_nodes, -1);
  for (int c = 0; c < int(s.chunks.size()); ++c) {
    const auto& ch = s.chunks[c];
    const auto& conn = blocks[ch.block].conn;
    for (Index e = ch.begin; e < ch.end; ++e)
      for (int k = 0; k < 8; ++k) {
        const Index node = conn[8 * std::size_t(e) + k];
        if (last[node] != c) {
          last[node] = c;
          ++count[node + 1];
        }
      }
  }
  for (std::size_t i = 0; i < num_nodes; ++i) count[i + 1] += count[i];
  std::vector<int> node_chunks(count[num_nodes]);
  std::vector<Index> fill(count.begin(), count.end() - 1);
  std::fill(last.begin(), last.end(), -1);
  for (int c = 0; c < int(s.chunks.size()); ++c) {
    const auto& ch = s.chunks[c];
    const auto& conn = blocks[ch.block].conn;
    for (Index e = ch.begin; e < ch.end; ++e)
      for (int k = 0; k < 8; ++k) {
        const Index node = conn[8 * std::size_t(e) + k];
        if (last[node] != c) {
          last[node] = c;
          node_chunks[fill[node]++] = c;
        }
      }
  }
  std::vector<int> color(s.chunks.size(), -1);
  std::vector<int> used_by(64, -1);  // used_by[color] == c: colour taken by a neighbour of chunk c
  for (int c = 0; c < int(s.chunks.size()); ++c) {
    const auto& ch = s.chunks[c];
    const auto& conn = blocks[ch.block].conn;
    for (Index e = ch.begin; e < ch.end; ++e)
      for (int k = 0; k < 8; ++k) {
        const Index node = conn[8 * std::size_t(e) + k];
        for (Index p = count[node]; p < count[node + 1]; ++p) {
          const int other = node_chunks[p];
          if (other != c && color[other] >= 0) {
            if (color[other] >= int(used_by.size())) used_by.resize(2 * color[other] + 1, -1);
            used_by[color[other]] = c;
          }
        }
      }
    int chosen = 0;
    while (chosen < int(used_by.size()) && used_by[chosen] == c) ++chosen;
    color[c] = chosen;
    if (chosen >= int(s.colors.size())) s.colors.resize(chosen + 1);
    s.colors[chosen].push_back(c);
  }
  return s;
}

}  // namespace plyimpact::model
