// `plyimpact mesh`: writes the scene's mesh for inspection, without running anything:
// <dir>/<scene>_mesh.vtu (cell data part_id, ply_index, ply_angle in degrees, material axes a/b/c;
// point data interface_id: the id of the delaminating interface a node lies on, 0 elsewhere) and
// <dir>/<scene>.msh (gmsh, physical groups per part and per interface side, impactor surface) and,
// for a rigid impactor, <dir>/<scene>_impactor.vtu (its surface quads; a deformable impactor is a
// part of the _mesh.vtu).
#pragma once

#include <filesystem>
#include <vector>

#include "config/scene.hpp"
#include "mesh/mesh.hpp"
#include "model/model.hpp"

namespace plyimpact::app {

/// Returns the paths written.
std::vector<std::filesystem::path> export_mesh(const config::Scene& scene, const mesh::Mesh& mesh,
                                               const model::Model& model, const std::filesystem::path& dir);

}  // namespace plyimpact::app
