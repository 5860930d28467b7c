// Which slave nodes a tiebreak contact ties, and to which point of which master segment — the
// set-up of *CONTACT_..._TIEBREAK on surfaces whose meshes need not match. A slave node is tied when
// (seed section 7.5.4, and the LS-DYNA manual's tied-contact remarks it follows):
//   1. it lies within the orthogonal projection of a master segment (natural coordinates within
//      [-1, 1] up to a round-off margin), and
//   2. its distance D from that segment satisfies D < 0.6 (master thickness + slave thickness)
//      (seed eq. 7.40).
// The thickness of a segment of a solid element is not defined by the manual's text we have;
// ASSUMPTION: the element's depth behind the face (reference volume / face area). SST and MST, when
// given, replace the slave and master thickness (LS-DYNA's contact thickness fields).
// Two more rules keep a solid's other faces out (a node one element above the interface lies within
// the tolerance of the master face below it): a slave node is considered only on a slave face whose
// outward normal opposes the master segment's (cosine below -0.5) and in front of that segment (not
// behind it by more than the tolerance: the far side of the master body), and its tributary area is a
// quarter of each slave face whose four corners are all tied. A node that is tied but lies on no
// fully tied face carries no area and is reported untied. Among several admissible segments a node
// takes the one at the smallest distance (the lowest segment index on a tie), so the result does not
// depend on the search order. Untied nodes are reported when they lie within twice the tolerance of
// a segment they face (nearer misses than that are what a user would want to hear about).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cohesive/segment_tiebreaks.hpp"
#include "core/types.hpp"

namespace plyimpact::interface {

struct TyingSurfaces {
  std::vector<Index> slave_faces;          // (num, 4) quads, outward normal t_xi x t_eta from the slave body
  std::vector<double> slave_thickness;     // (num) m
  std::vector<Index> master_faces;         // (num, 4) quads, outward from the master body
  std::vector<double> master_thickness;    // (num) m
};

struct UntiedNode {
  enum class Reason { OutsideProjection, TooFar, NoTiedFace };
  Index node = 0;
  Reason reason = Reason::OutsideProjection;
  double distance = 0;   // m, to the nearest admissible segment (TooFar)
  double tolerance = 0;  // m, 0.6 (t_m + t_s) there
};

struct TyingResult {
  std::vector<cohesive::SegmentTie> ties;
  std::vector<Index> tie_master_face;   // (num_ties) index into master_faces
  std::vector<UntiedNode> untied;       // slave nodes on facing slave faces that were not tied
  std::size_t slave_nodes = 0;          // nodes of the slave faces considered
};

TyingResult tie_slave_nodes(const TyingSurfaces& surfaces, const double* x_ref);

// "412 of 430 slave nodes tied; untied: 10 outside every master segment's projection, 8 farther than
// 0.6 (t_m + t_s) (node 17 at 0.41 mm, tolerance 0.30 mm), ..." — the warning LS-DYNA prints per node,
// summarised.
std::string tying_summary(const TyingResult& result, const double* x_ref);

}  // namespace plyimpact::interface
