// The mesher's interface and impactor types turned into the model's own (model/model.hpp), once,
// while the model is built: the run-time model carries no mesher type.
#pragma once

#include "mesh/mesh.hpp"
#include "model/model.hpp"

namespace plyimpact::model {

// Pairs and segments as meshed, plus each pair's tributary area and normal at the reference
// coordinates X (num_nodes, 3).
Interface make_interface(const mesh::Interface& meshed, const std::vector<double>& X);

Impactor make_impactor(const mesh::ImpactorMesh& meshed);

}  // namespace plyimpact::model
