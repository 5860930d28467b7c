// Size of a scene's mesh before it is made: nodes, elements and memory from the scene's sizes alone
// (plate and ply dimensions, element sizes, refinement, box element counts, impactor size), by
// arithmetic on the same 1-D distributions the meshers use, without gmsh. A scene whose mesh would
// exceed the element limit or the machine's memory is refused at the key that drives the count,
// before gmsh runs out of memory (std::bad_alloc) tens of seconds later.
#pragma once

#include <string>

#include "config/scene.hpp"

namespace plyimpact::mesh {

struct MeshSizeEstimate {
  double nodes = 0, elements = 0;  // whole scene (laminate or boxes, plus a meshed impactor)
  double bytes = 0;                // peak memory of meshing and running it
  std::string key;                 // key path that drives the count most ("laminate.element_size")
  std::string account;             // how the count arises: "1200 x 800 in-plane x 24 layers (24 plies x 1 per ply)"
};

// Memory per element and per node of meshing and building the run (gmsh's mesh, our mesh, model
// and solver state). Measured: `plyimpact check` of configs/sphere_on_plate.yaml at 0.20 and 0.82
// million elements (1.13 nodes per element) peaked at 0.26 and 0.86 GB, 0.98 kB per element with
// its nodes; these figures give 1.15 kB, a margin for the run's output buffers.
inline constexpr double kBytesPerElement = 700;
inline constexpr double kBytesPerNode = 400;
// Element limit when the scene gives no control.max_elements.
inline constexpr double kDefaultMaxElements = 2e7;

/// Estimate for `scene` (a mesh file is not estimated: its size is what it is).
MeshSizeEstimate estimate_mesh_size(const config::Scene& scene);

/// Total physical memory of the machine in bytes (0 if unknown).
double physical_memory_bytes();

/// Throws InputError at the driving key when the estimate exceeds the element limit
/// (control.max_elements, default kDefaultMaxElements) or, unless control.max_elements was given,
/// 80 % of `memory_bytes` (0: not checked).
void require_mesh_fits(const config::Scene& scene, const MeshSizeEstimate& estimate, double memory_bytes);

}  // namespace plyimpact::mesh
