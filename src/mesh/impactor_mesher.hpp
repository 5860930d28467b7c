// The impactor, from the gmsh scripts in geo/ (sphere, hemispherical_cylinder, flat_cylinder,
// cube), placed with its nose `gap` above the top of the plate. Every script meshes the solid in
// hexahedra (O-grid / cubed-sphere blocks for the round shapes). A rigid impactor keeps only the
// mesh's boundary quads and its mass properties (a rigid body needs no volume elements); a
// deformable one adds the hexahedra to Mesh::hex as its own part, with nodes of its own. Mass
// properties are those of the exact (not faceted) shape: mass = density x exact volume.
#pragma once

#include "config/scene.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

/// Adds Mesh::impactor for scene.impactor (which must be set), above the highest node of `mesh`.
/// @throws InputError if gmsh fails or produces a tangled element.
void add_impactor(const config::Scene& scene, Mesh& mesh);

/// Mass, centre of mass (nose tip at the origin, axis +z) and inertia about the centre of mass of
/// the exact shape with the impactor's mass.
ImpactorMesh impactor_mass_properties(const config::ImpactorSpec& spec);

}  // namespace plyimpact::mesh
