// Mesh: the geometry and topology handed to the model builder, whatever made it (the scene's box
// generator now, the gmsh layup mesher later). Node-major coordinates, LS-DYNA/VTK hexahedron order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "config/scene.hpp"
#include "core/types.hpp"

namespace plyimpact::mesh {

// A delaminating interface between plies `lower_ply` and `upper_ply` (0-based, upper = lower + 1):
// each ply has its own, coincident nodes there. lower_nodes[k] and upper_nodes[k] are a pair.
// Segments are quads (LS-DYNA/VTK quad order) on each side, outward from their ply:
// lower_segments[k] faces +z, upper_segments[k] is the same face seen from above (its partners in
// reverse order, facing -z).
struct Interface {
  int id = 0;  // 1-based interface number: interface i lies between plies i and i+1 (1-based)
  int lower_ply = 0, upper_ply = 0;
  double z = 0;                                        // m
  std::vector<Index> lower_nodes, upper_nodes;         // (num_pairs)
  std::vector<Index> lower_segments, upper_segments;   // (num_segments, 4)
};

// Nodes of a node set the generator computed itself (config::NodeSetSpec::Kind::Generated).
struct NodeList {
  std::string name;
  std::vector<Index> nodes;
};

// The impactor. Rigid: only its closed surface (own coordinates, outward quads) and its mass
// properties, no volume elements. Deformable: a hex part inside Mesh::hex (nodes not shared with
// anything else); the surface is still given in its own coordinates and surface_nodes maps it to
// Mesh nodes. Mass properties are those of the exact (not faceted) shape.
struct ImpactorMesh {
  bool rigid = true;
  int part = -1;                         // deformable: index into Scene::parts
  std::vector<double> surface_coords;    // (num_surface_nodes, 3), m
  std::vector<Index> surface_quads;      // (num_quads, 4) into surface_coords, outward normal
  std::vector<Index> surface_nodes;      // deformable: (num_surface_nodes) Mesh node of each surface node
  double mass = 0;                       // kg
  Vec3 centre_of_mass{0, 0, 0};          // m
  Mat3 inertia{};                        // kg m^2 about the centre of mass, global axes
  Vec3 velocity{0, 0, 0};                // m/s, initial
};

struct Mesh {
  std::vector<double> coords;    // (num_nodes, 3) reference coordinates, m
  std::vector<Index> hex;        // (num_elements, 8) node indices
  std::vector<int> element_part; // (num_elements) index into Scene::parts
  std::vector<int> element_ply;  // (num_elements) 0-based ply index, -1 outside a laminate; may be empty
  std::vector<Interface> interfaces;    // delaminating interfaces only
  std::vector<NodeList> node_sets;      // generated node sets (supports, symmetry planes)
  std::optional<ImpactorMesh> impactor;
  std::size_t num_nodes() const { return coords.size() / 3; }
  std::size_t num_elements() const { return element_part.size(); }
};

// Structured blocks from Scene::boxes; elements are numbered box by box, x fastest, then y, then z.
// With Scene::merge_coincident_nodes (the default) nodes of different boxes that coincide (within
// 1e-9 of the model size) become one node, so stacked boxes form one body (a laminate of plies);
// with it off every box is a separate body.
Mesh mesh_boxes(const config::Scene& scene);

}  // namespace plyimpact::mesh
