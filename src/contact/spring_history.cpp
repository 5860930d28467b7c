#include "contact/spring_history.hpp"

#include <utility>

namespace plyimpact::contact {

void SpringHistory::reset(std::size_t N, std::size_t S) {
  segment.assign(N, -1);
  engaged.assign(N, 0);
  gap.assign(N, 0.0);
  k.assign(N, 0.0);
  fn.assign(3 * N, 0.0);
  ft.assign(3 * N, 0.0);
  offset.assign(N, 0.0);
  exposure_offset.assign(N, 0.0);
  exposure_segment.assign(N, -1);
  new_node.assign(N, 0);
  new_segment.assign(S, 0);
  exposed_pass = false;
}

double SpringHistory::remap(const SegmentSetRemap& r) {
  SpringHistory old = std::move(*this);
  reset(r.new_node.size(), r.new_segment.size());
  double dropped = 0;
  for (std::size_t i = 0; i < r.node.size(); ++i) {
    const Index j = r.node[i];
    const bool segment_gone = old.segment[i] >= 0 && r.segment[std::size_t(old.segment[i])] < 0;
    if (old.engaged[i] && old.segment[i] >= 0 && (j < 0 || segment_gone))
      dropped += 0.5 * old.k[i] * old.gap[i] * old.gap[i];
    if (j < 0) continue;
    const std::size_t n = std::size_t(j);
    for (int d = 0; d < 3; ++d) {
      ft[3 * n + d] = old.ft[3 * i + d];
      fn[3 * n + d] = old.fn[3 * i + d];
    }
    offset[n] = old.offset[i];
    engaged[n] = old.engaged[i];
    gap[n] = old.gap[i];
    k[n] = old.k[i];
    // The segment of the last pass, where it survived: its neighbours keep the full release depth
    // (catch_rules), so a node pressed into the surface is not released by an erosion elsewhere.
    if (old.segment[i] >= 0) segment[n] = r.segment[std::size_t(old.segment[i])];
    // An exposure offset stays with its segment, or ends with it.
    const long e = old.exposure_segment[i] >= 0 ? r.segment[std::size_t(old.exposure_segment[i])] : -1;
    exposure_segment[n] = e;
    exposure_offset[n] = e >= 0 ? old.exposure_offset[i] : 0.0;
  }
  new_node = r.new_node;
  new_segment = r.new_segment;
  exposed_pass = true;
  return dropped;
}

void SpringHistory::visit_state(StateVisitor& v) {
  StateGroup group(v, "springs");
  v.array("segment", segment);
  v.array("engaged", engaged);
  v.array("gap", gap);
  v.array("stiffness", k);
  v.array("normal force", fn);
  v.array("friction force", ft);
  v.array("initial offset", offset);
  v.array("exposure offset", exposure_offset);
  v.array("exposure segment", exposure_segment);
  v.array("new node", new_node);
  v.array("new segment", new_segment);
  v.scalar("exposed pass", exposed_pass);
}

}  // namespace plyimpact::contact
