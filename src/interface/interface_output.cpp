#include "interface/interface_output.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace plyimpact::interface {

std::string InterfaceLayout::label() const {
  const auto degrees = [](double rad) { return long(std::lround(rad * 180 / std::numbers::pi)); };
  std::ostringstream s;
  s << "interface_" << id << " (plies " << lower_ply + 1 << "/" << upper_ply + 1 << ", " << degrees(lower_angle)
    << "/" << degrees(upper_angle) << ")";
  return s.str();
}

InterfaceLayout pair_layout(const model::Interface& itf) {
  InterfaceLayout l;
  l.id = itf.id;
  l.lower_ply = itf.lower_ply;
  l.upper_ply = itf.upper_ply;
  l.lower_angle = itf.lower_angle;
  l.upper_angle = itf.upper_angle;
  l.depth = itf.depth;
  l.lower_nodes = itf.lower_nodes;
  l.upper_nodes = itf.upper_nodes;
  l.quads = cohesive::pair_faces_from_segments(itf.lower_nodes, itf.lower_segments);
  l.area = itf.area;
  return l;
}

}  // namespace plyimpact::interface
