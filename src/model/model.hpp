// Model: everything about a run that does not change while it runs — reference geometry, lumped
// masses, materials, element blocks, node sets, constraints and the element schedule. Built once
// from a Scene and a Mesh (build_model), validated there (zero-volume elements, inadmissible
// orthotropic constants, conflicting constraints), then read-only. The mutable part lives in
// solver::State, so a model can be partitioned, and a state written and read back, later.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "config/scene.hpp"
#include "core/types.hpp"
#include "material/elastic.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::model {

enum class MaterialKind {
  IsotropicElastic,    // *MAT_001: hypoelastic, objective Hughes-Winget stress update
  OrthotropicElastic,  // *MAT_002: total Lagrangian, S = C : E, sigma = F S F^T / J
};

struct Material {
  std::string name, card;
  MaterialKind kind = MaterialKind::IsotropicElastic;
  double density = 0;       // reference density, kg/m^3
  double wave_modulus = 0;  // max over directions of rho c^2 (Pa): time step, hourglass, bulk q
  double wave_speed = 0;    // sqrt(wave_modulus / density)
  material::IsotropicConstants iso;    // MAT_001
  material::Stiffness6 c_material{};   // MAT_002, in material axes
  config::MaterialAxes axes;           // MAT_002
};

// One material orientation: axes and the stiffness rotated to global (reference) axes.
struct Orientation {
  Mat3 axes{};                  // rows a, b, c (global components)
  material::Stiffness6 c_global{};
};

enum class HourglassKind { None, Viscous, Stiffness };

// A homogeneous set of elements: one part, hence one material and one section.
struct ElementBlock {
  int part = 0;        // index into Model::parts
  int material = 0;    // index into Model::materials
  int elform = 1;      // 1 one-point + hourglass, 2 eight-point selectively reduced
  int ihq = 2;
  double qm = 0.1, q1 = 1.5, q2 = 0.06;
  std::vector<Index> conn;         // (num_elements, 8) global node indices
  std::vector<Index> element_id;   // (num_elements) 1-based ids, unique over the model
  std::vector<int> orientation;    // (num_elements) index into Model::orientations (MAT_002 only)
  std::vector<double> volume0;     // (num_elements) exact reference volume, m^3
  // (num_elements, 9) inverse of the centre Jacobian dX/dxi of the reference element, row-major; only
  // for total-Lagrangian materials with ELFORM 1, where F = J_x J_X^-1 at the centre (no gather of
  // reference coordinates and no matrix inverse in the cycle).
  std::vector<double> reference_jacobian_inverse;
  std::size_t size() const { return element_id.size(); }
  int points() const { return elform == 2 ? 8 : 1; }
  HourglassKind hourglass() const {
    if (elform != 1) return HourglassKind::None;
    return ihq >= 4 ? HourglassKind::Stiffness : HourglassKind::Viscous;
  }
  // IHQ 3 and 5 use the exact (Flanagan-Belytschko) volume and mean gradient.
  bool exact_gradient() const { return elform == 1 && (ihq == 3 || ihq == 5); }
};

struct Part {
  int id = 0;
  std::string name;
  int material = 0;
  int block = 0;
  std::string section;
};

struct NodeSet {
  std::string name;
  std::vector<Index> nodes;
};

// A piecewise-linear curve with constant extrapolation.
struct Curve {
  std::vector<double> t, y;
  double operator()(double time) const;
};

// One constrained degree of freedom (node * 3 + dof); curve < 0 means fixed (zero velocity).
struct ConstrainedDof {
  Index dof = 0;
  int curve = -1;
};

// A contiguous range of one block's elements, processed by one thread. Chunks of the same colour
// share no node, so their forces are scattered without races; the accumulation order at every
// node is fixed by (colour, chunk, element), independent of the number of threads.
struct Chunk {
  int block = 0;
  Index begin = 0, end = 0;
};

struct Schedule {
  std::vector<Chunk> chunks;
  std::vector<std::vector<int>> colors;  // chunk indices per colour
};

struct Model {
  std::string name;
  config::ControlSpec control;
  config::OutputSpec output;
  std::vector<double> X;        // (num_nodes, 3) reference coordinates
  std::vector<double> mass;     // (num_nodes) lumped mass, kg
  std::vector<double> v0;       // (num_nodes, 3) initial velocity
  std::vector<Material> materials;
  std::vector<Orientation> orientations;
  std::vector<Part> parts;
  std::vector<ElementBlock> blocks;
  std::vector<NodeSet> node_sets;
  std::vector<Curve> curves;
  std::vector<ConstrainedDof> constraints;
  std::vector<int> constrained_sets;  // node sets that carry a boundary condition (reaction output)
  Schedule schedule;
  // From the laminate mesher (issue 3); carried for the interface and contact subsystems, which do
  // not use them yet.
  std::vector<int> element_ply;                // (element_id - 1) -> 0-based ply, -1 if none; may be empty
  std::vector<mesh::Interface> interfaces;     // delaminating interfaces (coincident node pairs, segments)
  bool interfaces_bonded = false;  // true: the pairs are merged in the element connectivity (no tiebreak yet)
  std::optional<mesh::ImpactorMesh> impactor;  // impactor surface and mass properties

  std::size_t num_nodes() const { return mass.size(); }
  std::size_t num_elements() const;
};

// Builds and validates the model. Throws InputError naming the element, part or card at fault.
Model build_model(const config::Scene& scene, const mesh::Mesh& mesh);

// Chunks of at most `chunk_size` elements, greedily coloured so that chunks of one colour share no
// node. The chunk size is a constant (not the thread count) so results do not depend on threads.
Schedule make_schedule(const std::vector<ElementBlock>& blocks, std::size_t num_nodes, Index chunk_size = 256);

}  // namespace plyimpact::model
