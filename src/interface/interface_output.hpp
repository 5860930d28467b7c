// What the delamination outputs (the interface surface series, the C-scan, summary.json) need from a
// delaminating interface, whatever represents it: tiebreak node pairs today, cohesive elements or
// another kind later. A representation implements InterfaceSampleSource beside its force
// contributor; the outputs find it among the solver's contributors and never name the kind.
//   layout : fixed at the start: the sample points (each between a lower and an upper node, shown
//            at their mid-point, the current mid-surface), quads over them, each point's tributary
//            area, and where the interface lies in the laminate;
//   sample : per point, damage, mode mixity, opening and traction (cohesive::PairSample) for a
//            configuration, without changing the state.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cohesive/tiebreak_pairs.hpp"
#include "core/types.hpp"
#include "model/model.hpp"

namespace plyimpact::interface {

struct InterfaceLayout {
  int id = 0;                              // 1-based interface number (between plies id and id + 1)
  int lower_ply = 0, upper_ply = 0;        // 0-based ply indices
  double lower_angle = 0, upper_angle = 0; // rad
  double depth = 0;                        // m below the laminate's top (impacted) face
  std::vector<Index> lower_nodes, upper_nodes;  // (num_points) model nodes on either side
  std::vector<Index> quads;                // (num_quads, 4) point indices, counter-clockwise seen from above
  std::vector<double> area;                // (num_points) m^2 tributary area of each point
  std::size_t size() const { return lower_nodes.size(); }
  // "interface_3 (plies 3/4, 45/-45)": the 1-based plies and their angles in whole degrees.
  std::string label() const;
};

class InterfaceSampleSource {
 public:
  virtual ~InterfaceSampleSource() = default;
  virtual std::size_t num_interfaces() const = 0;
  virtual const InterfaceLayout& layout(std::size_t i) const = 0;
  // Samples of interface i for the configuration x ((num_nodes, 3)) into out[0 .. layout(i).size()).
  virtual void sample(std::size_t i, const double* x, cohesive::PairSample* out) const = 0;
};

// The layout of a model interface whose sample points are its node pairs (quads from its lower
// segments, areas and ply data from the model).
InterfaceLayout pair_layout(const model::Interface& itf);

}  // namespace plyimpact::interface
