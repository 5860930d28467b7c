// Orientation and boundary of an unstructured hexahedral mesh, for meshes gmsh builds from
// transfinite blocks (the impactors), whose elements may come out left-handed.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace plyimpact::mesh {

/// Makes every hexahedron of `hex` ((num, 8), LS-DYNA/VTK order) right-handed: an element whose
/// eight corner triple products are all negative is mirrored (nodes 1 <-> 3, 5 <-> 7). Returns the
/// number mirrored. @throws InputError if an element has corners of both signs (tangled) or a zero one.
int orient_hexes(const std::vector<double>& coords, std::vector<Index>& hex);

/// The faces used by exactly one element of a right-handed `hex` mesh, as quads (num, 4) with the
/// outward normal (counter-clockwise seen from outside), in element order.
std::vector<Index> boundary_quads(const std::vector<Index>& hex);

}  // namespace plyimpact::mesh
