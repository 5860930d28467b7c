// The mesh of a whole scene, whatever generates it: the box generator (Scene::boxes), or the gmsh
// laminate mesher plus the impactor (Scene::laminate, Scene::impactor).
#pragma once

#include <string>

#include "config/scene.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

/// @throws InputError
Mesh mesh_scene(const config::Scene& scene);

/// Writes `mesh` as a gmsh .msh file (format 4.1): one physical volume per part, one physical
/// surface per interface side ("interface_<id>_lower"/"_upper") and the rigid impactor's surface.
/// @throws RunError if the file cannot be written.
void write_msh(const config::Scene& scene, const Mesh& mesh, const std::string& path);

}  // namespace plyimpact::mesh
