// The segment set of a contact or an interface: the contact segments (outward quads) of one or two
// sides, each side the exterior faces of a set of hexahedral blocks (contact/surface.hpp) and
// optionally the impactor surface; the contact nodes (the segment nodes of each side, a node
// on both sides counted once per side); the nodes that carry a force (their union) and the
// per-segment and per-node data a penalty or tie law needs (PENOPT 1 stiffness K A^2 / V scaled by
// SLSFAC x SFS/SFM, masses, release depth).
//
// Identity across an eroding rebuild: a segment is its side and its sorted node quadruple, a contact
// node its model node and side. `rebuild` returns how the old indices map to the new ones, so that
// whoever keeps history per node or per segment (the penalty springs, an interface's damage) carries
// it over without knowing how the set was assembled.
//
// Layouts: per segment s, nodes (S, 4) in face order (outward normal t_xi x t_eta), owning element
// nodes (S, 8) (-1 for the impactor surface); per contact node i, its model node and side; force
// nodes u: model node, side-A flag, 1 / m (0 for rigid or massless nodes).
#pragma once

#include <array>
#include <vector>

#include "contact/surface.hpp"
#include "core/state_visitor.hpp"
#include "model/model.hpp"

namespace plyimpact::contact {

class BondedInterfaces;

// What a segment set is assembled from.
struct SegmentSetSpec {
  std::vector<int> blocks[2];          // element blocks of side A and B
  bool impactor[2] = {false, false};   // the impactor surface belongs to that side
  bool single = false;                 // one side in contact with itself (side B unused)
  double stiffness_scale[2] = {1, 1};  // SLSFAC x SFS (side A), SLSFAC x SFM (side B)
  double PENMAX = 0;                   // release depth, m (0: 0.4 V/A of the face's element, 0.4 sqrt(A) without volume)
  bool keep_orphans = false;           // ENMASS 1: a node left without segments stays a contact node
};

// The segment set of a contact definition (both sides, its SLSFAC/SFS/SFM, PENMAX, ENMASS).
SegmentSetSpec segment_set_spec(const model::Contact& def);

// How the indices of a set before a rebuild map to the new set (-1: gone).
struct SegmentSetRemap {
  std::vector<Index> node;         // (old contact nodes) new contact node
  std::vector<long> segment;       // (old segments) new segment
  std::vector<Index> force_node;   // (old force nodes) new force node
  std::vector<char> new_node;      // (new contact nodes) 1: not a contact node before
  std::vector<char> new_segment;   // (new segments) 1: not a segment before (a face erosion exposed)
};

class SegmentSet {
 public:
  SegmentSet() = default;
  // Assembles the set from the active elements (alive null: all) at x.
  SegmentSet(const model::Model& model, SegmentSetSpec spec, const std::vector<double>& x);

  // After element deletion: the set of the surviving elements' exterior faces at x.
  SegmentSetRemap rebuild(const AliveMask& alive, const std::vector<double>& x);

  bool single() const { return spec_.single; }
  // Grid (search side) whose segments contact node i can meet: the other side, or its own one.
  int other_side(std::size_t i) const { return spec_.single ? 0 : 1 - node_side_[i]; }

  // Segments.
  std::size_t num_segments() const { return seg_side_.size(); }
  const Index* segment_nodes(std::size_t s) const { return &seg_nodes_[4 * s]; }
  const Index* segment_owner(std::size_t s) const { return &seg_owner_[8 * s]; }
  int segment_side(std::size_t s) const { return seg_side_[s]; }
  double segment_stiffness(std::size_t s) const { return seg_k_[s]; }  // N/m, inf: no element
  double segment_mass(std::size_t s) const { return seg_mass_[s]; }    // half the element's, kg
  double segment_node_mass(std::size_t s) const { return seg_node_mass_[s]; }  // mean nodal mass
  double release_depth(std::size_t s) const { return seg_depth_[s]; }  // m
  // Identity of segment s across a rebuild: side and sorted nodes; all -1 for s < 0.
  std::array<Index, 5> segment_key(long s) const;
  // Segments of the same side sharing a node with s (ascending, s left out).
  const Index* neighbours_begin(std::size_t s) const { return nbr_.data() + nbr_start_[s]; }
  const Index* neighbours_end(std::size_t s) const { return nbr_.data() + nbr_start_[s + 1]; }

  // Contact nodes.
  std::size_t num_nodes() const { return node_id_.size(); }
  Index node_id(std::size_t i) const { return node_id_[i]; }
  int node_side(std::size_t i) const { return node_side_[i]; }
  double node_stiffness(std::size_t i) const { return node_k_[i]; }  // mean of its segments'
  double node_mass(std::size_t i) const { return node_mass_[i]; }
  double node_segment_mass(std::size_t i) const { return node_seg_mass_[i]; }  // mean of its segments'
  bool node_rigid(Index model_node) const { return node_rigid_[std::size_t(model_node)] != 0; }
  // Segments of contact node i's own side that hold it (ascending).
  const Index* own_begin(std::size_t i) const { return own_segs_.data() + own_start_[i]; }
  const Index* own_end(std::size_t i) const { return own_segs_.data() + own_start_[i + 1]; }

  // Force nodes (every node a contact force can act on).
  std::size_t num_force_nodes() const { return force_nodes_.size(); }
  const std::vector<Index>& force_nodes() const { return force_nodes_; }
  bool force_node_side_a(std::size_t u) const { return force_side_a_[u] != 0; }
  double force_node_inv_mass(std::size_t u) const { return force_inv_mass_[u]; }
  Index force_node_of_node(std::size_t i) const { return node_force_[i]; }
  const Index* force_nodes_of_segment(std::size_t s) const { return &seg_force_[4 * s]; }

  // Node-segment pairs a tiebreak holds (contact/bonded_interfaces), left out of the contact; null:
  // none. Not owned; it outlives the set.
  void exclude_bonded(const BondedInterfaces* rule) { bonded_ = rule; }
  const BondedInterfaces* bonded() const { return bonded_; }

  // Everything a rebuild changes (the constant parts, surface builders and rigid flags, are the
  // model's and are not visited).
  void visit_state(StateVisitor& visitor);

 private:
  // Who the contact nodes, segments and force nodes were before a rebuild: what the remap and the
  // orphans (ENMASS 1) need of the old set, swapped out of it rather than copying the whole set
  // (its surface builders alone hold a face record per element face).
  struct Identities {
    std::vector<Index> node_id;
    std::vector<char> node_side;
    std::vector<double> node_k;
    std::vector<Index> seg_nodes;
    std::vector<char> seg_side;
    std::vector<Index> force_nodes;
    std::vector<Index> nbr_start, nbr;
  };

  void assemble(const std::vector<double>& x, const AliveMask* alive, const Identities* old);
  // Segment s (the arrays sized by resize_segments) from its quad q and owning element.
  void set_segment(std::size_t s, const Index* q, const Index* owner, int side, double K, double volume,
                   double elem_mass, const std::vector<double>& x);
  void resize_segments(std::size_t S);
  void add_side(int side, const SurfaceBuilder& builder, const AliveMask* alive, const std::vector<double>& x);
  void collect_nodes(const Identities* old);
  void build_own_segments();
  // Same-side neighbours of every segment, searched (construction) or, after a rebuild, carried
  // over from `old` through the remap for segments whose nodes kept their segments.
  void build_neighbours(const Identities* old = nullptr, const SegmentSetRemap* remap = nullptr);
  void build_force_nodes();

  const model::Model* model_ = nullptr;
  SegmentSetSpec spec_;
  SurfaceBuilder builder_[2];
  const BondedInterfaces* bonded_ = nullptr;
  std::vector<char> node_rigid_;  // (num model nodes) slaved to a rigid body
  // Segments.
  std::vector<Index> seg_nodes_, seg_owner_;
  std::vector<char> seg_side_;
  std::vector<double> seg_k_, seg_mass_, seg_node_mass_, seg_depth_;
  std::vector<Index> nbr_start_, nbr_;
  // Contact nodes.
  std::vector<Index> node_id_;
  std::vector<char> node_side_;
  std::vector<double> node_k_, node_mass_, node_seg_mass_;
  std::vector<Index> own_start_, own_segs_;
  // Force nodes.
  std::vector<Index> force_nodes_;
  std::vector<Index> force_of_model_;  // (num model nodes) force node, -1
  std::vector<char> force_side_a_;
  std::vector<double> force_inv_mass_;
  std::vector<Index> node_force_, seg_force_;  // force node of each contact node / segment node
  Identities previous_;  // scratch of rebuild (capacity kept between rebuilds); not run state
};

}  // namespace plyimpact::contact
