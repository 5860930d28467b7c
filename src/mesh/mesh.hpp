// Mesh: the geometry and topology handed to the model builder, whatever made it (the scene's box
// generator now, the gmsh layup mesher later). Node-major coordinates, LS-DYNA/VTK hexahedron order.
#pragma once

#include <vector>

#include "config/scene.hpp"
#include "core/types.hpp"

namespace plyimpact::mesh {

struct Mesh {
  std::vector<double> coords;    // (num_nodes, 3) reference coordinates, m
  std::vector<Index> hex;        // (num_elements, 8) node indices
  std::vector<int> element_part; // (num_elements) index into Scene::parts
  std::size_t num_nodes() const { return coords.size() / 3; }
  std::size_t num_elements() const { return element_part.size(); }
};

// Structured blocks from Scene::boxes; elements are numbered box by box, x fastest, then y, then z.
// With Scene::merge_coincident_nodes (the default) nodes of different boxes that coincide (within
// 1e-9 of the model size) become one node, so stacked boxes form one body (a laminate of plies);
// with it off every box is a separate body.
Mesh mesh_boxes(const config::Scene& scene);

}  // namespace plyimpact::mesh
