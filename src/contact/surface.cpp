#include "contact/surface.hpp"

#include <algorithm>
#include <array>

namespace plyimpact::contact {

SurfaceBuilder::SurfaceBuilder(const model::Model& model, const std::vector<int>& blocks) {
  std::vector<std::pair<std::array<Index, 4>, long>> keys;
  for (int b : blocks) {
    const auto& blk = model.blocks[b];
    for (Index e = 0; e < Index(blk.size()); ++e)
      for (int f = 0; f < 6; ++f) {
        std::array<Index, 4> k;
        for (int j = 0; j < 4; ++j) k[j] = blk.conn[8 * std::size_t(e) + kHexFaces[f][j]];
        std::sort(k.begin(), k.end());
        keys.push_back({k, long(faces_.size())});
        faces_.push_back({b, e, f});
      }
  }
  neighbour_.assign(faces_.size(), -1);
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i + 1 < keys.size(); ++i)
    if (keys[i].first == keys[i + 1].first) {
      neighbour_[keys[i].second] = keys[i + 1].second;
      neighbour_[keys[i + 1].second] = keys[i].second;
      ++i;
    }
}

bool SurfaceBuilder::active(const AliveMask* alive, int block, Index e) const {
  if (!alive || (*alive)[block].empty()) return true;
  return (*alive)[block][e] != 0;
}

std::vector<SurfaceBuilder::Face> SurfaceBuilder::exterior(const AliveMask* alive) const {
  std::vector<Face> out;
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    const Face& f = faces_[i];
    if (!active(alive, f.block, f.element)) continue;
    const long n = neighbour_[i];
    if (n >= 0 && active(alive, faces_[n].block, faces_[n].element)) continue;
    out.push_back(f);
  }
  return out;
}

}  // namespace plyimpact::contact
