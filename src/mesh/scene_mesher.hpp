// The mesh of a whole scene, whatever generates it: the box generator (Scene::boxes), or the gmsh
// laminate mesher, or a .msh file (Scene::mesh_file), plus the impactor (Scene::impactor).
#pragma once

#include <string>

#include "config/scene.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

/// @throws InputError
Mesh mesh_scene(const config::Scene& scene);

/// Writes `mesh` as a binary gmsh .msh file (format 4.1, coordinates in m): one physical volume per part
/// (hexahedron e has element tag e + 1), one physical surface per interface side
/// ("interface_<id>_lower"/"_upper"), one physical point group per generated node set and the rigid
/// impactor's surface. mesh/msh_reader reads it back.
/// @throws RunError if the file cannot be written.
void write_msh(const config::Scene& scene, const Mesh& mesh, const std::string& path);

}  // namespace plyimpact::mesh
