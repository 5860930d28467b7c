// Model: everything about a run that does not change while it runs — reference geometry, lumped
// masses, materials, element blocks, node sets, constraints and the element schedule. Built once
// from a Scene and a Mesh (build_model), validated there (zero-volume elements, inadmissible
// orthotropic constants, conflicting constraints), then read-only. The mutable part lives in
// solver::State, so a model can be partitioned, and a state written and read back, later.
#pragma once

#include <optional>
#include <string>
#include <cstdint>
#include <vector>

#include "config/scene.hpp"
#include "core/types.hpp"
#include "model/erosion_neighbours.hpp"
#include "model/mass_scaling_report.hpp"
#include "material/composite_damage.hpp"
#include "material/elastic.hpp"
#include "material/johnson_cook.hpp"
#include "material/plasticity.hpp"

namespace plyimpact::mesh {
struct Mesh;
}

namespace plyimpact::model {

enum class MaterialKind {
  IsotropicElastic,    // *MAT_001: hypoelastic, objective Hughes-Winget stress update
  OrthotropicElastic,  // *MAT_002: total Lagrangian, S = C : E, sigma = F S F^T / J
  Rigid,               // *MAT_020: no stress; the part moves as one rigid body (solver/rigid_body)
  Plastic,             // *MAT_003 / *MAT_024: hypoelastic J2 plasticity (material/plasticity)
  CompositeDamage,     // *MAT_054 / *MAT_055: incremental, in current material axes (material/composite_damage)
  JohnsonCook,         // *MAT_015 / *MAT_098: hypoelastic J2 Johnson-Cook, EOS pressure (material/johnson_cook)
};

struct Material {
  std::string name, card;
  MaterialKind kind = MaterialKind::IsotropicElastic;
  double density = 0;       // reference density, kg/m^3
  double wave_modulus = 0;  // max over directions of rho c^2 (Pa): time step, hourglass, bulk q
  double wave_speed = 0;    // sqrt(wave_modulus / density)
  // Bulk modulus K for the SOFT 0 contact stiffness (Pa): E / (3 (1 - 2 nu)) for MAT_001/MAT_020,
  // the Reuss bound 1 / sum_{i,j<=3} S_ij for MAT_002 (our choice; LS-DYNA's is not published).
  double bulk_modulus = 0;
  // Young's modulus along the material c axis (Pa): EC of an orthotropic card, E of an isotropic one.
  // Through a ply's thickness (its c axis); the process-zone length of its interfaces uses it.
  double modulus_c = 0;
  material::IsotropicConstants iso;    // MAT_001
  material::Stiffness6 c_material{};   // MAT_002, in material axes
  material::MaterialAxes axes;         // MAT_002, MAT_054
  material::PlasticityParams plastic;  // MAT_003, MAT_024
  material::CompositeDamageParams composite;  // MAT_054/055
  material::JohnsonCookParams johnson_cook;   // MAT_015/098
  // History values per integration point (plastic strain, back stress; damage flags, ...).
  int history_size() const {
    return kind == MaterialKind::Plastic           ? material::kPlasticityHistory
           : kind == MaterialKind::CompositeDamage ? material::kCompositeDamageHistory
           : kind == MaterialKind::JohnsonCook     ? material::kJohnsonCookHistory
                                                   : 0;
  }
  // Elements of this material can be deleted by a failure criterion of the material.
  bool can_fail() const {
    return kind == MaterialKind::CompositeDamage || (kind == MaterialKind::Plastic && plastic.failure_strain > 0) ||
           (kind == MaterialKind::JohnsonCook && johnson_cook.can_fail());
  }
  bool has_axes() const { return kind == MaterialKind::OrthotropicElastic || kind == MaterialKind::CompositeDamage; }
};

// One material orientation: axes and the stiffness rotated to global (reference) axes.
using Orientation = material::Orientation;

enum class HourglassKind { None, Viscous, Stiffness };

// A homogeneous set of elements: one part, hence one material and one section.
struct ElementBlock {
  int part = 0;        // index into Model::parts
  int material = 0;    // index into Model::materials
  // 1 one-point + hourglass, 2 eight-point selectively reduced, -2 the same with assumed natural
  // transverse shear for thin elements (element/hex8_ans.hpp)
  int elform = 1;
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
  bool rigid = false;  // MAT_020: not in the element schedule; its nodes follow a RigidBody
  // (num_elements) mass scaling (solver/mass_scaling): the element's step is its computed step
  // times this factor, sqrt((m + dm) / m) for its added mass dm; empty = no element scaled.
  std::vector<double> step_scale;
  // (num_elements) ELFORM -2: the element's thin natural direction (0 xi, 1 eta, 2 zeta), the one
  // with the shortest centre base vector dX/dxi_c at the reference geometry (zeta, then eta, on a
  // tie within 1 %); empty otherwise.
  std::vector<std::uint8_t> thin_axis;
  // (num_elements, 2) ELFORM -2: the reference volumes of the element's two B-bar layers (the
  // Gauss points either side of the mid-surface, element::ans_layer), for the F-bar of
  // total-Lagrangian materials; empty otherwise.
  std::vector<double> layer_volume0;
  // (num_elements) *MAT_054 with erosion_reference_length: the factor on the element's erosion
  // strains (erosion_strain_scale); empty = 1 for every element.
  std::vector<double> erosion_scale;
  // *MAT_054 with erosion_nonlocal: the elements shorter than the reference length also erode at the
  // card's strains where the mean strain over this neighbourhood reaches them.
  ErosionNeighbours erosion_neighbours;
  std::size_t size() const { return element_id.size(); }
  bool fully_integrated() const { return elform == 2 || elform == -2; }
  int points() const { return fully_integrated() ? 8 : 1; }
  HourglassKind hourglass() const {
    if (elform != 1) return HourglassKind::None;
    return ihq >= 4 ? HourglassKind::Stiffness : HourglassKind::Viscous;  // IHQ 4, 5, 6 accumulate forces
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

// A rigid body (*MAT_020 part, or the meshed surface-only impactor). Its nodes are slaved: the solver
// sums their forces and moments, integrates the body and sets their positions and velocities.
struct RigidBody {
  std::string name;              // part name, or "impactor"
  int part = -1;                 // index into Model::parts; -1 for the surface-only impactor
  std::vector<Index> nodes;      // slaved nodes (sorted)
  double mass = 0;               // kg
  Vec3 centre{0, 0, 0};          // centre of mass at t = 0, m
  Mat3 inertia{};                // about the centre of mass, global axes at t = 0, kg m^2
  Vec3 velocity{0, 0, 0};        // initial centre-of-mass velocity, m/s
  Vec3 angular_velocity{0, 0, 0};  // initial, rad/s
  std::array<bool, 6> fixed{};   // x y z rx ry rz (global)
  std::array<int, 6> curve{-1, -1, -1, -1, -1, -1};  // prescribed dof -> index into Model::curves
};

// Planar rigid wall; see config::RigidWallSpec. nodes: the slave nodes (deformable, with mass).
struct RigidWall {
  std::string name;
  Vec3 point{0, 0, 0}, normal{0, 0, 1}, velocity{0, 0, 0};
  Vec3 u{1, 0, 0}, v{0, 1, 0};   // in-plane axes of a finite wall (v = normal x u)
  double length_u = 0, length_v = 0;  // 0: infinite
  double friction = 0;
  std::vector<Index> nodes;
};

// One side of a contact: element blocks whose exterior faces form the surface, and/or the meshed
// rigid impactor's surface quads (Model::impactor_quads).
struct ContactSide {
  std::vector<int> blocks;
  bool impactor = false;
  std::string label;   // part names, for messages
};

struct Contact {
  config::ContactSpec spec;
  ContactSide a, b;    // b unused for single-surface contact
};

// A delaminating interface between plies `lower_ply` and `upper_ply` (0-based, upper = lower + 1),
// where each ply has its own coincident nodes: lower_nodes[k] and upper_nodes[k] are pair k. Each
// pair carries its tributary area (a quarter of every interface segment it is a corner of) and the
// unit normal from the lower to the upper ply (area-weighted mean of those segments' normals), in
// the reference configuration. Segments are quads on each side, outward from their ply (the lower
// side's face +normal, the upper side's are the same faces in reverse order).
struct Interface {
  int id = 0;  // 1-based interface number: interface i lies between plies i and i+1 (1-based)
  int lower_ply = 0, upper_ply = 0;
  double z = 0;                                        // m, reference height
  std::vector<Index> lower_nodes, upper_nodes;         // (num_pairs)
  std::vector<double> area;                            // (num_pairs) m^2
  std::vector<double> normal;                          // (num_pairs, 3)
  std::vector<Index> lower_segments, upper_segments;   // (num_segments, 4)
  // Tiebreak law (and pre-crack) of the interface; empty: its pairs are merged (bonded plies).
  std::optional<config::InterfaceLawSpec> tiebreak;
  // Where the interface lies in the laminate, for the outputs: the angles of its two plies (rad) and
  // its depth below the laminate's top face (m), the face the impactor strikes.
  double lower_angle = 0, upper_angle = 0;
  double depth = 0;
  // Pa: the smaller through-thickness modulus (Material::modulus_c) of its two plies, the E of the
  // process-zone length M E G_c / tau^2 (cohesive::process_zone_strength); 0 when not a laminate's.
  double transverse_modulus = 0;
  std::size_t num_pairs() const { return lower_nodes.size(); }
};

// The meshed impactor as the run sees it: its closed surface (own coordinates, outward quads) and
// the mass properties of the exact (not faceted) shape. A deformable impactor is also a hex part
// of the model; its surface_nodes map the surface to model nodes.
struct Impactor {
  bool rigid = true;
  std::vector<double> surface_coords;    // (num_surface_nodes, 3), m
  std::vector<Index> surface_quads;      // (num_quads, 4) into surface_coords, outward normal
  std::vector<Index> surface_nodes;      // deformable: (num_surface_nodes) model node of each surface node
  double mass = 0;                       // kg
  Vec3 centre_of_mass{0, 0, 0};          // m
  Mat3 inertia{};                        // kg m^2 about the centre of mass, global axes
  Vec3 velocity{0, 0, 0};                // m/s, initial
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
  // From the laminate mesher, converted once by build_model (the run never sees mesher types).
  std::vector<int> element_ply;                // (element_id - 1) -> 0-based ply, -1 if none; may be empty
  std::vector<Interface> interfaces;  // delaminating interfaces (coincident node pairs, segments)
  bool interfaces_bonded = false;  // true: some interface's pairs are merged in the element connectivity (no law)
  std::optional<Impactor> impactor;  // impactor surface and mass properties
  // Contact and rigid bodies (built only when the scene asks for them).
  std::vector<RigidBody> rigid_bodies;
  std::vector<RigidWall> rigid_walls;
  std::vector<Contact> contacts;
  // Tiebreak contacts (spec.tiebreak set): side a the slave surface, b the master (interface/surface_tiebreaks).
  std::vector<Contact> tiebreak_contacts;
  Vec3 gravity{0, 0, 0};                // m/s^2
  std::optional<config::CouponSpec> coupon;  // fracture-coupon measurements (run/coupon_probe)
  // The rigid impactor's surface, when a contact or rigid body uses it: its nodes are appended to
  // the model's nodes (mass = impactor mass / number of surface nodes, for the contact stiffness)
  // and these quads index them. impactor_bulk_modulus: from its material, 0 if none (then its
  // segments take the opposite side's stiffness).
  std::vector<Index> impactor_quads;    // (num_quads, 4)
  double impactor_bulk_modulus = 0;
  MassScalingReport mass_scaling;  // control.dt2ms < 0: what was added (solver::apply_mass_scaling)

  std::size_t num_nodes() const { return mass.size(); }
  std::size_t num_elements() const;
};

// Builds and validates the model. Throws InputError naming the element, part or card at fault.
Model build_model(const config::Scene& scene, const mesh::Mesh& mesh);

// Part of build_model: rigid bodies (MAT_020 parts, the meshed impactor), rigid walls, contacts and
// gravity from the scene; appends the rigid impactor's surface nodes when something uses them.
void add_rigid_bodies_and_contacts(const config::Scene& scene, Model& model);

// Reference coordinates of the 8 nodes `conn` of one element, component-major (x[i][k]: component i
// of node k), as the hex8 helpers take them.
inline void gather_reference(const std::vector<double>& X, const Index* conn, double x[3][8]) {
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) x[i][k] = X[3 * std::size_t(conn[k]) + i];
}

// Chunks of at most `chunk_size` elements, greedily coloured so that chunks of one colour share no
// node. The chunk size is a constant (not the thread count) so results do not depend on threads.
Schedule make_schedule(const std::vector<ElementBlock>& blocks, std::size_t num_nodes, Index chunk_size = 256);

}  // namespace plyimpact::model
