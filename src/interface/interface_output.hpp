// What the delamination outputs (the interface surface series, the C-scan, summary.json, a coupon's
// crack length) need from a delaminating interface, whatever represents it: tiebreak node pairs,
// *MAT_138 cohesive elements, or the segment ties of a tiebreak contact. Each representation
// implements InterfaceSampleSource beside its force contributor; the outputs find it among the
// solver's contributors and never name the kind.
//   sample points : where the law is evaluated (a pair, an integration point of a cohesive element,
//                   a tied slave node), each with its area and reference position;
//   display       : quads over vertices; each vertex shows one sample point's values at a position
//                   that is a fixed weighted sum of model nodes (so it follows the deformation), and
//                   owns the quarter of each of its quads at its corner. The quads are laid out so
//                   that each point's vertices own exactly its area: a pair is a vertex of the
//                   interface's quads; a tie is a vertex of the fully tied slave faces; an element's
//                   integration point g owns the element's quadrant g, shown as a sub-quad whose four
//                   vertices all show it (so the display, the C-scan and the areas agree);
//   sample        : per point, damage, mode mixity, opening and traction (cohesive::PairSample) for
//                   a configuration, without changing the state; damage: the stored damage.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cohesive/cohesive_elements.hpp"
#include "cohesive/point_sample.hpp"
#include "cohesive/segment_tiebreaks.hpp"
#include "core/types.hpp"
#include "model/model.hpp"

namespace plyimpact::interface {

struct InterfaceLayout {
  // Laminate interface i (between plies i and i + 1) has id i; tiebreak contacts are numbered after
  // the laminate's interfaces, in scene order.
  int id = 0;
  std::string contact;                     // name of the tiebreak contact; empty for a laminate interface
  int lower_ply = 0, upper_ply = 0;        // 0-based ply indices (laminate interfaces)
  double lower_angle = 0, upper_angle = 0; // rad
  double depth = 0;                        // m below the impacted face (the top of the laminate or of the tied parts)

  std::vector<double> area;                // (num_points) m^2 tributary area of each sample point
  std::vector<double> reference;           // (num_points, 3) m, reference position on the mid-surface

  std::vector<Index> vertex_point;         // (num_vertices) the sample point each vertex shows
  std::vector<Index> vertex_offset{0};     // (num_vertices + 1) CSR into vertex_node, vertex_weight
  std::vector<Index> vertex_node;
  std::vector<double> vertex_weight;
  std::vector<Index> quads;                // (num_quads, 4) vertex indices

  std::size_t size() const { return area.size(); }
  std::size_t num_vertices() const { return vertex_point.size(); }
  // Vertex positions for configuration x ((num_nodes, 3)) into out ((num_vertices, 3)).
  void vertex_positions(const double* x, double* out) const;
  // "interface_3 (plies 3/4, 45/-45)" (1-based plies, angles in whole degrees) or "tiebreak contact glue".
  std::string label() const;
  // Appends a vertex showing `point` at sum_k weights[k] x[nodes[k]].
  void add_vertex(Index point, std::initializer_list<Index> nodes, std::initializer_list<double> weights);
};

class InterfaceSampleSource {
 public:
  virtual ~InterfaceSampleSource() = default;
  virtual std::size_t num_interfaces() const = 0;
  virtual const InterfaceLayout& layout(std::size_t i) const = 0;
  // Samples of interface i for the configuration x ((num_nodes, 3)) into out[0 .. layout(i).size()).
  virtual void sample(std::size_t i, const double* x, cohesive::PairSample* out) const = 0;
  // The stored damage of interface i's points (as of the last force pass), (layout(i).size()).
  virtual const std::vector<double>& damage(std::size_t i) const = 0;
  // Delaminated area of interface i (m^2) as history.csv's delaminated_area_<i> counts it (pairs
  // released because their ply eroded away left out; the samples still show them separated).
  virtual double delaminated_area(std::size_t i) const = 0;
};

// A model interface whose sample points are its node pairs (quads from its lower segments).
InterfaceLayout pair_layout(const model::Model& model, const model::Interface& itf);

// A model interface with cohesive elements: points element-major (4 per element), quadrant g of each
// element shown as a sub-quad (corner g, the midpoints of its two edges, the centre).
InterfaceLayout cohesive_layout(const model::Model& model, const model::Interface& itf,
                                const cohesive::CohesiveElements& elements);

// A tiebreak contact: a vertex per tie midway between the slave node and its master point, the quads
// the slave faces (slave_faces, (num, 4) node indices) whose four nodes are tied. `blocks`: the blocks
// of both sides, whose highest reference z is the top the depth is measured from.
InterfaceLayout tie_layout(const model::Model& model, int id, const std::string& contact,
                           const cohesive::SegmentTiebreaks& ties, const std::vector<Index>& slave_faces,
                           const std::vector<int>& blocks);

}  // namespace plyimpact::interface
