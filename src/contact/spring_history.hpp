// What the penalty contact remembers per contact node from one pass to the next: the spring of the
// last pass (segment, gap, stiffness, normal and friction force), the initial-penetration offset,
// the exposure offset an eroding rebuild may give it, and what the last rebuild added. Kept across
// an eroding rebuild through the segment set's remap (a node keeps its spring where its segment
// survived). Layout: per contact node i of the segment set, vectors (N) or (N, 3).
#pragma once

#include <vector>

#include "contact/segment_set.hpp"
#include "core/state_visitor.hpp"

namespace plyimpact::contact {

struct SpringHistory {
  std::vector<long> segment;       // segment the node was in contact with at the last pass, -1
  std::vector<char> engaged;       // in contact at the last pass (also when its segment did not survive a rebuild)
  // The spring of the last pass: gap g (0: none), stiffness k and normal force (N, 3); its
  // potential 0.5 k g^2 is what a segment switch starts from (penalty_contact).
  std::vector<double> gap, k, fn;
  std::vector<double> ft;          // (N, 3) tangential (friction) force of the last pass
  std::vector<double> offset;      // initial-penetration baseline gap (<= 0)
  // Eroding rebuild: in the pass after it (exposed_pass) a node without a spring that is found
  // behind a segment the rebuild added (new_segment), or a node new to the surface (new_node), gets
  // its gap as an offset on that segment (exposure_offset <= 0 on exposure_segment, kept across
  // rebuilds, relaxed as the node backs out, cleared when it leaves that segment).
  std::vector<double> exposure_offset;
  std::vector<long> exposure_segment;
  std::vector<char> new_node, new_segment;  // (N), (S)
  bool exposed_pass = false;

  // Fresh history for a set of N nodes and S segments (nothing engaged, no offsets).
  void reset(std::size_t N, std::size_t S);
  // After a rebuild: each surviving node keeps its history, its segment where that survived.
  // Returns the potential 0.5 k g^2 of the springs that end with it (their node or segment eroded).
  double remap(const SegmentSetRemap& remap);

  // Gap offset of node i on segment s: the initial-penetration offset plus the exposure offset
  // when s is the segment it was found behind.
  double offset_on(std::size_t i, long s) const {
    return offset[i] + (s == exposure_segment[i] ? exposure_offset[i] : 0.0);
  }
  // Ends node i's spring (released): its force, friction and exposure offset.
  void release(std::size_t i) {
    exposure_segment[i] = -1;  // an exposure offset ends with the contact
    exposure_offset[i] = 0;
    for (int d = 0; d < 3; ++d) ft[3 * i + d] = 0;
    gap[i] = k[i] = 0;
    for (int d = 0; d < 3; ++d) fn[3 * i + d] = 0;
  }

  void visit_state(StateVisitor& visitor);
};

}  // namespace plyimpact::contact
