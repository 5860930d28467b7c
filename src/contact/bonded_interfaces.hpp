// Which node-segment pairs of a penalty contact a tiebreak holds (docs/theory.md, "Inter-ply
// contact"): the plies' single-surface contact spans the delaminating interfaces, whose duplicated
// nodes lie on the faces of the ply across. While a pair is bonded its tiebreak carries the
// interface, in tension and in compression; a contact spring there would double the compression
// stiffness and soak up energy at every bonded node. Once the pair has separated (damage 1) its
// tiebreak still acts as node-to-node contact (no tension; compression and friction), so the faces
// around its partner stay with that contact too. The rule, for a contact node n of interface I:
//   - n's pair bonded:    no segment with a corner on the other side of I (the partner's faces,
//                         and every face touching the bonded interface from across it);
//   - n's pair separated: no segment with the partner as a corner (its own contact acts there);
//                         faces beyond them, which n meets after sliding more than an element, and
//                         faces erosion exposes elsewhere take part.
// Nodes of no interface, and segments with no corner on I, are never excluded: plies meeting
// through a hole eroded in the ply between them, and a ply buckling onto itself, make springs.
// Interfaces without a bound damage state (cohesive elements, or before binding) count as bonded.
// A pair released for good (its ply eroded away, cohesive::TiebreakPairs::release_pair) acts no
// more, so it excludes nothing: its nodes meet every face, as nodes of no interface do.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"

namespace plyimpact::contact {

class BondedInterfaces {
 public:
  BondedInterfaces() = default;
  // The node pairs of every interface of `model` with a tiebreak law (tiebreak pairs or cohesive).
  explicit BondedInterfaces(const model::Model& model);

  bool empty() const { return lower_.empty(); }
  std::size_t num_pairs() const { return lower_.size(); }
  // Interface number `interface_id` takes its pairs' damage (pair order of model::Interface) from
  // `damage` (null: bonded all along) and which are released for good from `released` (null:
  // none). The vectors must outlive this object.
  void bind(int interface_id, const std::vector<double>* damage, const std::vector<char>* released = nullptr);
  bool bound(int interface_id) const;

  bool bonded(Index pair) const {
    const std::vector<double>* d = damage_[std::size_t(interface_of_[std::size_t(pair)])];
    return d == nullptr || (*d)[std::size_t(pair - first_pair_[std::size_t(interface_of_[std::size_t(pair)])])] < 1.0;
  }

  bool released(Index pair) const {
    const int slot = interface_of_[std::size_t(pair)];
    const std::vector<char>* r = released_[std::size_t(slot)];
    return r != nullptr && (*r)[std::size_t(pair - first_pair_[std::size_t(slot)])] != 0;
  }

  // Whether contact node `node` may not meet the segment with corners q[0..3].
  bool excludes(Index node, const Index* q) const {
    const int code = code_[std::size_t(node)];
    if (code < 0) return false;
    const Index pair = code >> 1;
    const int side = code & 1;
    if (released(pair)) return false;
    if (!bonded(pair)) {
      const Index partner = side == 0 ? upper_[std::size_t(pair)] : lower_[std::size_t(pair)];
      return q[0] == partner || q[1] == partner || q[2] == partner || q[3] == partner;
    }
    const int itf = interface_of_[std::size_t(pair)];
    for (int a = 0; a < 4; ++a) {
      const int c = code_[std::size_t(q[a])];
      if (c >= 0 && (c & 1) != side && interface_of_[std::size_t(c >> 1)] == itf) return true;
    }
    return false;
  }

 private:
  std::vector<int> code_;            // (num model nodes) 2 pair + side (0 lower, 1 upper), -1: none
  std::vector<Index> lower_, upper_; // (pairs, all interfaces in model order) model nodes
  std::vector<int> interface_of_;    // (pairs) slot of its interface
  std::vector<int> ids_;             // (slots) interface number
  std::vector<Index> first_pair_;    // (slots) index of its first pair
  std::vector<const std::vector<double>*> damage_;  // (slots) bound damage, null: bonded
  std::vector<const std::vector<char>*> released_;  // (slots) bound release flags, null: none
};

}  // namespace plyimpact::contact
