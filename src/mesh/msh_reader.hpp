// Reads a volume mesh of 8-node hexahedra from a gmsh .msh file (Scene::mesh_file) through the
// gmsh API, so every format gmsh reads (MSH 4.1 ASCII and binary, also 2.2) is accepted.
//  - Hexahedra of a physical volume belong to the scene part of that name, or, for an unnamed
//    group, to the part whose id is the group's tag. Every hexahedron must be in exactly one
//    physical volume; any other volume element (tetrahedra, prisms, 20/27-node hexahedra) is
//    refused with its type and count.
//  - Elements keep the order of their element tags and nodes that of their node tags; nodes no
//    hexahedron uses are left out. Coordinates are scaled by MeshFileSpec::length_scale.
//  - Named physical groups of points, curves and surfaces (and volumes) become node sets
//    (Mesh::node_sets) for the scene's `from_mesh` node sets.
//  - Physical surface pairs "interface_<id>_lower" / "interface_<id>_upper" of quadrangles, as
//    `plyimpact mesh` writes a laminate's delaminating interfaces, become Mesh::interfaces
//    (segment k of each side is the same face; partner nodes coincide).
#pragma once

#include "config/scene.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

/// @throws InputError naming the file (and, for a missing node set, the scene line).
Mesh read_msh(const config::Scene& scene);

}  // namespace plyimpact::mesh
