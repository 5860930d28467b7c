#include "contact/bonded_interfaces.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/error.hpp"

namespace plyimpact::contact {

BondedInterfaces::BondedInterfaces(const model::Model& model) {
  code_.assign(model.num_nodes(), -1);
  for (const auto& itf : model.interfaces) {
    if (!itf.tiebreak) continue;  // merged: one node, nothing to hold apart
    const int slot = int(ids_.size());
    ids_.push_back(itf.id);
    first_pair_.push_back(Index(lower_.size()));
    damage_.push_back(nullptr);
    released_.push_back(nullptr);
    for (std::size_t p = 0; p < itf.num_pairs(); ++p) {
      const Index pair = Index(lower_.size());
      const Index nodes[2] = {itf.lower_nodes[p], itf.upper_nodes[p]};
      for (int side = 0; side < 2; ++side) {
        // A node is on one interface at most (a ply has a thickness between its two faces); the
        // rule keeps one pair per node, so a second would be silently ignored.
        if (code_[std::size_t(nodes[side])] >= 0)
          throw std::logic_error((msg() << "node " << nodes[side] + 1 << " belongs to two interface pairs").str());
        code_[std::size_t(nodes[side])] = 2 * pair + side;
      }
      lower_.push_back(nodes[0]);
      upper_.push_back(nodes[1]);
      interface_of_.push_back(slot);
    }
  }
}

void BondedInterfaces::bind(int interface_id, const std::vector<double>* damage, const std::vector<char>* released) {
  const auto it = std::find(ids_.begin(), ids_.end(), interface_id);
  if (it == ids_.end()) throw std::logic_error((msg() << "interface " << interface_id << " has no tiebreak pairs").str());
  const std::size_t slot = std::size_t(it - ids_.begin());
  const std::size_t n = (slot + 1 < ids_.size() ? std::size_t(first_pair_[slot + 1]) : lower_.size()) -
                        std::size_t(first_pair_[slot]);
  if (damage != nullptr && damage->size() != n)
    throw std::logic_error(
        (msg() << "interface " << interface_id << ": " << damage->size() << " damage values for " << n << " pairs").str());
  if (released != nullptr && released->size() != n)
    throw std::logic_error(
        (msg() << "interface " << interface_id << ": " << released->size() << " release flags for " << n << " pairs").str());
  damage_[slot] = damage;
  released_[slot] = released;
}

bool BondedInterfaces::bound(int interface_id) const {
  const auto it = std::find(ids_.begin(), ids_.end(), interface_id);
  return it != ids_.end() && damage_[std::size_t(it - ids_.begin())] != nullptr;
}

}  // namespace plyimpact::contact
