// The impactor: its surface from the gmsh scripts in geo/ (sphere.geo, hemispherical_cylinder.geo)
// placed with its nose `gap` above the top of the plate, and its mass properties from the exact
// shape (the faceted surface is only used for contact). A rigid impactor carries no volume
// elements (a rigid body needs only its surface and mass properties).
#pragma once

#include "config/scene.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

/// Adds Mesh::impactor for scene.impactor (which must be set), above the highest node of `mesh`.
/// @throws InputError for a shape or option not available yet, or if gmsh fails.
void add_impactor(const config::Scene& scene, Mesh& mesh);

/// Mass, centre of mass (nose tip at the origin, axis +z) and inertia about the centre of mass of
/// the exact shape with the impactor's mass.
ImpactorMesh impactor_mass_properties(const config::ImpactorSpec& spec);

}  // namespace plyimpact::mesh
