// Laminated plate -> structured ply-by-ply hex mesh with gmsh. gmsh's built-in kernel
// builds a patch layout in the plane z = 0 (patches cut at the refined zone and the support
// window), transfinite + recombined, and one extrusion per ply with `elements_per_ply` layers
// (toolchain recipe). Node coordinates are then snapped to the exact 1-D distributions of
// axis_grid.hpp (gmsh places transfinite nodes only to ~1e-8), which makes interface pairs, plane
// node sets and nested refinement levels exact. Delaminating interfaces get their own nodes on the
// upper ply (gmsh would merge them, G8). Elements are numbered ply by ply, bottom ply first.
#pragma once

#include "config/scene.hpp"
#include "mesh/axis_grid.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

/// Meshes scene.laminate (which must be set). Fills coords, hex, element_part, element_ply,
/// interfaces and the laminate's generated node sets (supports, symmetry_x, symmetry_y).
/// @throws InputError if gmsh fails or its mesh is not the expected structured grid.
Mesh mesh_laminate(const config::Scene& scene);

/// The 1-D node distribution the mesher uses along x (axis 0) or y (axis 1): extent, break points,
/// refined zone, sizes and level (mesh/size_estimate counts elements from it without gmsh).
AxisSpec laminate_axis(const config::LaminateSpec& lam, int axis);

}  // namespace plyimpact::mesh
