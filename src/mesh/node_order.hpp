// Node numbering that follows the elements. gmsh numbers a laminate's nodes by geometric entity
// (corners, edges, faces of every ply first), so neighbouring elements' nodes lie far apart in the
// node arrays and every ply's nodes are spread over the whole range. The solver splits its
// passes over threads by element chunks in part order and updates each node on the thread that
// computes its elements (solver/node_chunk_owners): with the nodes numbered in the order the
// elements first use them, part by part, a ply's nodes are one contiguous range, a thread's nodes
// are its own cache lines, and an element's eight nodes are close together.
#pragma once

#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

// Renumbers the nodes of `mesh` in the order of their first use by its hexahedra, taken part by
// part (Mesh::element_part, increasing; each part's elements in mesh order); nodes no hexahedron
// uses keep their relative order after those. Every node index in the mesh (hexahedra,
// interfaces, node sets, a deformable impactor's surface) is mapped; coordinates are permuted.
void number_nodes_in_element_order(Mesh& mesh);

}  // namespace plyimpact::mesh
