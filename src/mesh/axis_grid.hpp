// One-dimensional node distributions of the structured plate mesh. An axis is cut into bands at
// break points (plate edges, support window, refined zone); each band is meshed uniformly or with a
// geometric progression that grows from the zone's element size to the plate's. Refinement level k
// uses 2^k n elements and ratio r^(1/2^k): every node of level k is a node of level k+1 (nested
// meshes). The exact coordinates computed here are also what the gmsh nodes are snapped to.
#pragma once

#include <vector>

namespace plyimpact::mesh {

struct Band {
  double x0 = 0, x1 = 0;  // x0 < x1
  int elements = 1;
  double ratio = 1;       // size of element j+1 / size of element j, going from x0 to x1
  // The level-0 band this one refines: node j sits where the level-0 formula puts node j/2^k, so
  // the nodes shared with a coarser level are bit-identical, not just equal to round-off.
  int base_elements = 1;
  double base_ratio = 1;
};

struct AxisSpec {
  double lo = 0, hi = 0;              // modelled extent
  std::vector<double> breaks;         // extra break points (any order; outside (lo, hi) ignored)
  double zone_lo = 0, zone_hi = 0;    // refined zone (zone_hi <= zone_lo: none)
  double size = 0, zone_size = 0;     // element sizes outside / inside the zone
  int level = 0;                      // refinement level
};

/// Bands of one axis, from lo to hi.
std::vector<Band> axis_bands(const AxisSpec& spec);

/// Node coordinates of consecutive bands (shared end points once); the ends are exactly lo, hi and
/// each break point.
std::vector<double> band_nodes(const std::vector<Band>& bands);

}  // namespace plyimpact::mesh
