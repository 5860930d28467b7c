#include "mesh/scene_mesher.hpp"

#include <gmsh.h>

#include <filesystem>
#include <new>
#include <numeric>

#include "mesh/gmsh_session.hpp"
#include "mesh/impactor_mesher.hpp"
#include "mesh/laminate_mesher.hpp"
#include "mesh/msh_reader.hpp"
#include "mesh/node_order.hpp"
#include "mesh/size_estimate.hpp"

namespace plyimpact::mesh {

namespace {

// Runs one mesher; a failure inside it (gmsh's messages name no scene line, and running out of
// memory names nothing) becomes an input error at the key that sets the mesh's size.
template <class F>
void with_key(const config::Scene& scene, const std::string& key, const MeshSizeEstimate& estimate, F&& mesher) {
  try {
    mesher();
  } catch (const std::bad_alloc&) {
    throw InputError(config::at(scene.where_of(key))
                     << "out of memory while meshing (estimate: " << estimate.elements << " elements, "
                     << estimate.account << "); found a mesh larger than this machine can hold; allowed a "
                     << "coarser " << key << " (or fewer plies, a lower refinement)");
  } catch (const InputError& e) {
    throw InputError(config::at(scene.where_of(key)) << e.what() << " (the mesh made from " << key
                                                     << " and the sizes beside it)");
  }
}

}  // namespace

Mesh mesh_scene(const config::Scene& scene) {
  const MeshSizeEstimate estimate = estimate_mesh_size(scene);
  require_mesh_fits(scene, estimate, physical_memory_bytes());
  Mesh m;
  if (scene.mesh_file) m = read_msh(scene);
  else if (scene.laminate) {
    with_key(scene, "laminate.element_size", estimate, [&] { m = mesh_laminate(scene); });
    number_nodes_in_element_order(m);
  }
  else m = mesh_boxes(scene);
  if (scene.impactor) with_key(scene, "impactor.element_size", estimate, [&] { add_impactor(scene, m); });
  return m;
}

void write_msh(const config::Scene& scene, const Mesh& mesh, const std::string& path) {
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
    throw RunError(msg() << path << ": cannot write the .msh file: no directory " << parent.string());
  GmshModel model("export");
  gmsh_call("writing " + path, [&] {
    namespace gm = gmsh::model;
    // All nodes on one discrete volume; elements of each part on their own volume (gmsh allows
    // elements to use nodes classified elsewhere).
    const int nodes_entity = gm::addDiscreteEntity(3);
    std::vector<std::size_t> tags(mesh.num_nodes());
    std::iota(tags.begin(), tags.end(), std::size_t(1));
    gm::mesh::addNodes(3, nodes_entity, tags, mesh.coords);
    // Hexahedron e has tag e + 1, so a reader that orders by tag (mesh/msh_reader) gets the
    // elements back in their original order.
    std::size_t next_element = mesh.num_elements() + 1;
    for (std::size_t p = 0; p < scene.parts.size(); ++p) {
      std::vector<std::size_t> etags, enodes;
      for (std::size_t e = 0; e < mesh.num_elements(); ++e) {
        if (mesh.element_part[e] != int(p)) continue;
        etags.push_back(e + 1);
        for (int k = 0; k < 8; ++k) enodes.push_back(std::size_t(mesh.hex[8 * e + k]) + 1);
      }
      if (etags.empty()) continue;
      const int v = gm::addDiscreteEntity(3);
      gm::mesh::addElementsByType(v, 5, etags, enodes);
      const int phys = gm::addPhysicalGroup(3, {v}, scene.parts[p].id);
      gm::setPhysicalName(3, phys, scene.parts[p].name);
    }
    auto add_quads = [&](const std::vector<Index>& quads, std::size_t node_offset, const std::string& name) {
      std::vector<std::size_t> etags, enodes;
      for (std::size_t q = 0; q < quads.size() / 4; ++q) {
        etags.push_back(next_element++);
        for (int k = 0; k < 4; ++k) enodes.push_back(std::size_t(quads[4 * q + k]) + node_offset + 1);
      }
      const int s = gm::addDiscreteEntity(2);
      gm::mesh::addElementsByType(s, 3, etags, enodes);  // 3 = 4-node quadrangle
      gm::setPhysicalName(2, gm::addPhysicalGroup(2, {s}), name);
    };
    for (const auto& itf : mesh.interfaces) {
      add_quads(itf.lower_segments, 0, "interface_" + std::to_string(itf.id) + "_lower");
      add_quads(itf.upper_segments, 0, "interface_" + std::to_string(itf.id) + "_upper");
    }
    // Generated node sets (supports, symmetry planes) as physical groups of points, one point
    // element per node, so a scene read from this file can name them (`from_mesh`).
    for (const auto& set : mesh.node_sets) {
      std::vector<std::size_t> etags, enodes;
      for (Index n : set.nodes) {
        etags.push_back(next_element++);
        enodes.push_back(std::size_t(n) + 1);
      }
      const int pt = gm::addDiscreteEntity(0);
      gm::mesh::addElementsByType(pt, 15, etags, enodes);  // 15 = 1-node point
      gm::setPhysicalName(0, gm::addPhysicalGroup(0, {pt}), set.name);
    }
    if (mesh.impactor && mesh.impactor->rigid) {
      const auto& imp = *mesh.impactor;
      const int s = gm::addDiscreteEntity(2);
      std::vector<std::size_t> stags(imp.surface_coords.size() / 3);
      std::iota(stags.begin(), stags.end(), mesh.num_nodes() + 1);
      gm::mesh::addNodes(2, s, stags, imp.surface_coords);
      add_quads(imp.surface_quads, mesh.num_nodes(), "impactor_rigid_surface");
    }
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    // Binary: coordinates exactly as computed (gmsh's ASCII writer prints 16 significant digits,
    // which does not always round-trip a double), so a scene run from the file matches the original.
    gmsh::option::setNumber("Mesh.Binary", 1);
    gmsh::write(path);
  });
  if (!std::filesystem::exists(path, ec)) throw RunError(msg() << path << ": gmsh did not write the .msh file");
}

}  // namespace plyimpact::mesh
