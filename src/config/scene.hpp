// Scene: the typed, validated description of one run, as read from a YAML file. Every value is SI
// (m, kg, s, N, Pa, J, rad); config/scene_loader converts from the scene's unit system or from
// values written with units ("157 GPa"). Material fields keep their LS-DYNA card names so a user can
// carry a keyword card across. Nothing here depends on yaml-cpp.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cohesive/law_parameters.hpp"
#include "cohesive/mat138_parameters.hpp"
#include "config/johnson_cook_spec.hpp"
#include "config/mat054_spec.hpp"
#include "config/material_axes.hpp"
#include "core/error.hpp"
#include "core/types.hpp"

namespace plyimpact::config {

// Where a value came from, for messages that point the user at the right line.
struct SourceLocation {
  std::string file;
  int line = 0;    // 1-based; 0 = unknown
  int column = 0;  // 1-based
  std::string key_path;  // e.g. "materials.ply.EA"
};

// Start of an error message about a scene value: "file:line:col: key.path: " (just "file: " when
// the line is unknown, or the override's text for a value given with --set).
inline msg at(const SourceLocation& w) {
  msg m;
  m << w.file;
  if (w.line > 0) m << ":" << w.line << ":" << w.column;
  m << ": " << w.key_path << ": ";
  return m;
}

// *MAT_001 (*MAT_ELASTIC): isotropic, hypoelastic for solids.
struct MatElastic {
  double RO = 0, E = 0, PR = 0;
};

// *MAT_002 (*MAT_ORTHOTROPIC_ELASTIC). PRBA = nu_ba (the minor ratio for a = fibre), as on the card.
struct MatOrthotropicElastic {
  double RO = 0, EA = 0, EB = 0, EC = 0, PRBA = 0, PRCA = 0, PRCB = 0, GAB = 0, GBC = 0, GCA = 0;
  MaterialAxes axes;
};

// *MAT_020 (*MAT_RIGID): E and PR only set the contact stiffness. CMO = 1 with CON1 (translations:
// 0 free, 1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all) and CON2 (rotations, same codes) fixes global
// degrees of freedom of the body, as on the LS-DYNA card.
struct MatRigid {
  double RO = 0, E = 0, PR = 0;
  int CMO = 0, CON1 = 0, CON2 = 0;
};

// *MAT_003 (*MAT_PLASTIC_KINEMATIC): bilinear elasto-plastic, BETA 0 kinematic .. 1 isotropic,
// Cowper-Symonds SRC/SRP, failure (erosion) at effective plastic strain FS (0 = none).
struct MatPlasticKinematic {
  double RO = 0, E = 0, PR = 0, SIGY = 0, ETAN = 0, BETA = 0, SRC = 0, SRP = 0, FS = 0;
};

// *MAT_024 (*MAT_PIECEWISE_LINEAR_PLASTICITY): isotropic hardening from the curve LCSS (effective
// plastic strain, yield stress), given inline; without it SIGY and ETAN; rate factor C/P; FAIL.
struct MatPiecewiseLinear {
  double RO = 0, E = 0, PR = 0, SIGY = 0, ETAN = 0, FAIL = 0, C = 0, P = 0;
  std::vector<double> LCSS_strain, LCSS_stress;
};

struct MaterialSpec {
  std::string name;
  std::string card;  // "MAT_001", "MAT_002" or "MAT_020" (LS-DYNA keyword number)
  std::variant<MatElastic, MatOrthotropicElastic, MatRigid, MatPlasticKinematic, MatPiecewiseLinear, MatCompositeDamage,
               MatJohnsonCook, MatSimplifiedJohnsonCook>
      params;
  SourceLocation where;
};

// *SECTION_SOLID + *HOURGLASS: element formulation, hourglass control and bulk viscosity.
struct SectionSpec {
  std::string name;
  int ELFORM = 1;     // 1: one-point with hourglass control; 2: 8-point selectively reduced
  int IHQ = 2;        // 1,2,3 viscous; 4,5 stiffness (LS-DYNA explicit default for solids is 2)
  double QM = 0.1;    // hourglass coefficient
  double Q1 = 1.5;    // quadratic bulk viscosity coefficient
  double Q2 = 0.06;   // linear bulk viscosity coefficient
  SourceLocation where;
};

struct PartSpec {
  std::string name;
  int id = 0;               // 1-based, unique; written to output as part_id
  std::string material;     // MaterialSpec::name
  std::string section;      // SectionSpec::name
  double beta = 0;          // rad: ply angle about the material c axis, added to the card's BETA
  SourceLocation where;
};

// Structured block of hexahedra (the "box" generator): origin, edge lengths, element counts.
struct BoxSpec {
  std::string part;
  Vec3 origin{0, 0, 0};
  Vec3 size{1, 1, 1};
  std::array<int, 3> elements{1, 1, 1};
  SourceLocation where;
};

// A volume mesh read from a gmsh .msh file (mesh: {file, length_unit}) instead of boxes or a
// laminate: hexahedra of each physical volume form the part of that name (or, unnamed, of that id);
// physical surfaces and points give node sets (NodeSetSpec::Kind::Generated, "from_mesh").
struct MeshFileSpec {
  std::string path;          // as resolved against the scene file's folder
  double length_scale = 1;   // m per coordinate unit of the file (mesh.length_unit)
  SourceLocation where;
};

// Node selection. Exactly one of the selectors is used.
struct NodeSetSpec {
  // Generated: the nodes are listed by the mesh generator (mesh::Mesh::node_sets, same name), e.g.
  // a laminate's supports and symmetry planes, which select exact grid lines rather than regions,
  // or a physical group of a mesh file.
  enum class Kind { Box, Plane, Part, All, Generated };
  std::string name;
  Kind kind = Kind::All;
  Vec3 box_min{0, 0, 0}, box_max{0, 0, 0};  // Box: closed, with tolerance
  int plane_axis = 0;                        // Plane: 0=x 1=y 2=z
  double plane_value = 0;
  double tolerance = 0;  // m; 0 = automatic (1e-6 of the model size)
  std::string part;      // Part
  SourceLocation where;
};

// Piecewise-linear curve y(t); constant extrapolation outside the given range.
struct CurveSpec {
  std::vector<double> t, y;
};

struct BoundaryConditionSpec {
  enum class Kind { Fixed, Velocity };
  std::string node_set;
  Kind kind = Kind::Fixed;
  std::array<bool, 3> dofs{false, false, false};  // which of x, y, z the condition acts on
  CurveSpec curve;      // Velocity: v(t) in m/s applied to every selected dof
  SourceLocation where;
};

// Velocity V reached from rest over `ramp` seconds along V (1 - cos(pi t / ramp)) / 2 (zero
// acceleration at both ends, so a quasi-static coupon is not struck), then held: the curve samples
// the ramp at `segments` intervals (the largest deviation from the cosine is pi^2 / (16 n^2) of V,
// 0.02 % for the default 64). ramp = 0 gives the step {0: V}.
CurveSpec smooth_ramp_curve(double velocity, double ramp, int segments = 64);

// The measurements of a fracture coupon (DCB, ENF, MMB), written as history.csv columns `load`,
// `opening` and `crack_length` (run/coupon_probe; docs/coupons.md):
//   load         = the reaction of node set `load` along `axis`, signed positive when it opens the
//                  specimen (pulls `upper` up or pushes `lower` down);
//   opening      = mean displacement of `upper` minus that of `lower` along `axis` (a side left
//                  empty is the fixed ground);
//   crack_length = from the load line x = crack_origin along +x to the damage front of interface
//                  `interface`: midway between the furthest row of separated pairs (damage 1,
//                  pre-crack included) and the next row of pairs.
struct CouponSpec {
  enum class Type { DCB, ENF, MMB };
  Type type = Type::DCB;
  int interface = 0;           // 1-based interface number (between plies i and i + 1)
  std::string load;            // node set with a prescribed velocity (a constrained set)
  std::string upper, lower;    // node sets; at least one
  int axis = 2;                // 0 = x, 1 = y, 2 = z
  double crack_origin = 0;     // m, x of the load line
  SourceLocation where;
};

struct InitialVelocitySpec {
  std::string part;      // either a part...
  std::string node_set;  // ...or a node set (exactly one is non-empty)
  Vec3 velocity{0, 0, 0};
  SourceLocation where;
};

// *TERMINATION_CONTACT: the run ends, as a normal termination, once the contact's resultant force has
// stayed at or below THRES for DUR, counted from ACTIM on (run/contact_termination.hpp).
struct TerminationContactSpec {
  std::string contact;  // CID: the contact's name
  double ACTIM = 0;     // s, activation time
  int DOF = 0;          // 0: magnitude of the resultant; 1, 2, 3: its global x, y, z component
  double THRES = 0;     // N, largest force that counts as none
  double DUR = 0;       // s, how long it must stay so
  SourceLocation where;
};

struct ControlSpec {
  double termination_time = 0;  // s (required)
  double tssfac = 0.9;          // *CONTROL_TIMESTEP TSSFAC
  // *CONTROL_TIMESTEP DT2MS, s: negative = mass scaling, elements whose stable step is below
  // |DT2MS| get mass so that it equals |DT2MS| (solver/mass_scaling); 0 = off.
  double dt2ms = 0;
  double endmas = 0;            // *CONTROL_TERMINATION ENDMAS, %: refuse more added mass than this; 0 = off
  double dt_min_ratio = 1e-3;   // stop if dt < dt_min_ratio * dt0
  double erode_tsmin = 0;       // s: erode elements whose step falls below it (ERODE=1 with TSMIN); 0 = off
  double energy_ratio_limit = 1.5;  // stop if the energy ratio exceeds it (energy is being created); 0 = off
  double hourglass_warn_ratio = 0.1;  // warn when E_hg > ratio * E_int
  long max_cycles = 0;          // 0 = no limit (LS-DYNA ENDCYC: the run stops there)
  // Refusals before the run (docs/commands.md, "Input limits"): a mesh estimated above
  // max_elements, a run whose estimated cycle count exceeds cycle_limit. 0 = the default limit.
  long max_elements = 0;
  long cycle_limit = 0;
  int threads = 0;              // 0 = OpenMP default
  std::optional<TerminationContactSpec> termination_contact;
};

struct OutputSpec {
  enum class Compression { None, ZLib, LZ4 };
  double interval = 0;          // s between VTU frames; 0 = 20 frames over the run
  double history_interval = 0;  // s between history.csv rows; 0 = 1000 rows over the run
  double restart_interval = 0;  // s between restart dumps (*DATABASE_BINARY_D3DUMP); 0 = only at the end
  Compression compression = Compression::ZLib;  // of the VTU frames (lossless)
};

// One ply of a laminate, bottom (z = 0) to top.
struct PlySpec {
  double angle = 0;       // rad, about the laminate normal (+z), from the material's a axis (AOPT 2)
  double thickness = 0;   // m
  std::string material;   // MaterialSpec::name
  int part = -1;          // index into Scene::parts (one part per ply or per sub-laminate block)
  int zone_part = -1;     // its elements in the impact zone (LaminateSpec::impact_zone_section); -1: none
};

// A support of the plate; the loader turns it into a Generated node set plus a fixed condition.
struct SupportSpec {
  enum class Kind { Clamped, Window };
  std::string name;                    // node set name
  Kind kind = Kind::Clamped;
  std::array<bool, 4> edges{};         // Clamped: x0, x1, y0, y1 (the full side faces of the plate)
  double window_x = 0, window_y = 0;   // Window: opening centred on the impact point, bottom face
  std::array<bool, 3> fix{};           // dofs fixed on the set
  SourceLocation where;
};

// Traction-separation law of one delaminating interface (*CONTACT_..._TIEBREAK card 4) and the
// region of it that starts separated (a pre-crack: its pairs start with damage 1).
struct InterfaceLawSpec {
  enum class Model { Tiebreak, Cohesive };  // node pairs (tiebreak) or 8-node *MAT_138 elements
  Model model = Model::Tiebreak;
  cohesive::TractionLawParams law;          // Cohesive: the OPTION 9 law of `mat138`
  cohesive::Mat138Params mat138;            // Cohesive only: the card as given
  bool has_precrack = false;
  double precrack_x[2] = {0, 0}, precrack_y[2] = {0, 0};  // m, region of the plate (y: whole width if not given)
  // process_zone_elements (a plyimpact key, not on the LS-DYNA cards): each segment's NFLS and SFLS
  // lowered to the strength whose cohesive zone spans this many segments of its length (Turon et al.
  // 2007; cohesive::process_zone_strength), where that is below the card's; 0 = the card's everywhere.
  double process_zone_elements = 0;
  SourceLocation where;
};

// Laminated plate meshed ply by ply with gmsh (mesh/laminate_mesher): x along the length, y along
// the width, z through the thickness. A symmetry plane keeps the half x <= length/2 (or y <= width/2).
struct LaminateSpec {
  double length = 0, width = 0;
  std::vector<PlySpec> plies;
  std::string section;               // SectionSpec::name for every ply part
  int elements_per_ply = 1;          // through each ply's thickness
  double element_size = 0;           // in-plane, m
  double impact_x = 0, impact_y = 0; // impact point (default: plate centre)
  // Refined zone: zone_x by zone_y centred on the impact point, meshed uniformly at
  // zone_element_size, graded (geometric progression) out to element_size. 0 = no zone.
  double zone_x = 0, zone_y = 0, zone_element_size = 0;
  // Impact zone: the elements whose centre lies in impact_zone_x by impact_zone_y, centred on the
  // impact point, form parts of their own (one per ply part, named as it with "_zone") with the
  // section impact_zone_section, e.g. fully integrated plies where they crush, one-point ones
  // outside. Empty section: no impact zone.
  double impact_zone_x = 0, impact_zone_y = 0;
  std::string impact_zone_section;
  SourceLocation impact_zone_where;
  int refinement_level = 0;          // every in-plane division halved this many times (nested meshes)
  // delaminating[i]: the interface between plies i and i+1 (0-based) gets duplicated nodes.
  std::vector<bool> delaminating;
  // interface_law[i]: the tiebreak law of delaminating interface i (empty: `model: merged`, the
  // pair's nodes are merged and the plies stay bonded).
  std::vector<std::optional<InterfaceLawSpec>> interface_law;
  bool group_plies = false;          // adjacent equal-angle plies without a delaminating interface share a part
  std::array<bool, 2> symmetry{};    // symmetry planes x = length/2, y = width/2 (half/quarter model)
  std::vector<SupportSpec> supports;
  SourceLocation where;
};

// Impactor, built by mesh/impactor_mesher from the gmsh scripts in geo/. Its axis is z; the nose
// points down at the impact point, `gap` above the top of the plate.
struct ImpactorSpec {
  enum class Shape { HemisphericalCylinder, Sphere, FlatCylinder, Cube };
  Shape shape = Shape::HemisphericalCylinder;
  double diameter = 0;       // m (Cube: edge length)
  double length = 0;         // m, overall length along the axis (cylinders; 0 = diameter)
  double mass = 0;           // kg; 0 = from the material's density
  double density = 0;        // kg/m^3 used for the impactor (stated, or mass / nominal volume)
  bool rigid = true;         // rigid: surface + mass properties only; else a hex part
  std::string material;      // MaterialSpec::name (deformable; for rigid optional, gives the density)
  int part = -1;             // index into Scene::parts (deformable only)
  double gap = 0;            // m between the nose and the top of the plate
  double x = 0, y = 0;       // axis position (default: the laminate's impact point)
  Vec3 velocity{0, 0, 0};    // m/s
  double element_size = 0;   // m; 0 = diameter / 8
  SourceLocation where;
};

// Extra conditions on a rigid part (MAT_020): fixed degrees of freedom (x y z rx ry rz, global)
// and a prescribed velocity of the centre of mass (translations) or angular velocity (rotations).
struct RigidBodySpec {
  std::string part;                          // PartSpec::name of a MAT_020 part, or "impactor"
  std::array<bool, 6> fix{};                 // x y z rx ry rz
  std::array<bool, 6> prescribed{};          // dofs that follow `curve`
  CurveSpec curve;                           // m/s (rad/s for rotations) vs time
  SourceLocation where;
};

// Planar rigid wall (*RIGIDWALL_PLANAR): nodes may not cross the plane through `point` with
// normal `normal` (the allowed side). Finite when length_u > 0: the rectangle point + a u + b v,
// 0 <= a <= length_u, 0 <= b <= length_v, v = normal x u. Moves at a constant `velocity`.
struct RigidWallSpec {
  std::string name;
  Vec3 point{0, 0, 0};
  Vec3 normal{0, 0, 1};       // normalised by the loader
  Vec3 velocity{0, 0, 0};     // m/s
  double friction = 0;        // Coulomb coefficient (0 frictionless)
  Vec3 u{1, 0, 0};            // finite wall: first edge direction (normalised, orthogonal to normal)
  double length_u = 0, length_v = 0;  // m; 0 = infinite
  std::vector<std::string> parts;     // slave parts; empty = every deformable part
  SourceLocation where;
};

// Penalty contact (*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, *CONTACT_AUTOMATIC_SINGLE_SURFACE and
// their ERODING_ variants). Card names and defaults as in LS-DYNA (theory.md section 8).
struct ContactSpec {
  enum class Type { SurfaceToSurface, SingleSurface };
  enum class InitialPenetration { Move, Offset };
  std::string name;
  Type type = Type::SurfaceToSurface;
  bool eroding = false;                       // ERODING_: rebuild the surface when elements are deleted
  std::vector<std::string> surface_a, surface_b;  // part names ("impactor": the meshed rigid impactor)
  int SOFT = 0;           // 0 bulk-modulus, 1 soft constraint, 2 segment-based
  double SOFSCL = 0.1;    // SOFT 1 scale
  double SLSFAC = 0.1;    // *CONTROL_CONTACT penalty scale
  double SFS = 1, SFM = 1;      // side A / side B scale factors
  double FS = 0, FD = 0, DC = 0, VDC = 0;  // friction and viscous damping (VDC in % of critical)
  double PENMAX = 0;      // m, release depth; 0 = 0.4 x element thickness across the segment
  double MAXPAR = 1.025;  // parametric tolerance of the projection
  double DTSTIF = 0;      // s, step in the SOFT 1/2 stiffness; 0 = initial solution step
  int BSORT = 0;          // bucket sort at least every BSORT cycles; 0: when the motion requires it
  int ENMASS = 0;         // eroding: 0 drop nodes left without elements, 1 keep them as mass points
  InitialPenetration initial_penetration = InitialPenetration::Move;
  // Tiebreak (type tiebreak_surface_to_surface): surface_a is the slave side, surface_b the master
  // side; the law of card 4 and the contact thicknesses of eq. 7.40 (0: the elements' depth).
  std::optional<cohesive::TractionLawParams> tiebreak;
  double SST = 0, MST = 0;  // m
  SourceLocation where;
};

struct Scene {
  std::string name;       // scene file stem, used for the .pvd name
  std::string file;       // path of the YAML file
  std::string unit_system;  // as declared ("SI", "mm-t-s-MPa", "mm-kg-ms-GPa")
  ControlSpec control;
  OutputSpec output;
  std::vector<MaterialSpec> materials;
  std::vector<SectionSpec> sections;
  std::vector<PartSpec> parts;
  std::vector<BoxSpec> boxes;
  bool merge_coincident_nodes = true;  // mesh.merge_nodes: boxes sharing a face share its nodes
  std::optional<MeshFileSpec> mesh_file;  // mesh.file: read by mesh/msh_reader
  std::vector<NodeSetSpec> node_sets;
  std::vector<BoundaryConditionSpec> boundary_conditions;
  std::vector<InitialVelocitySpec> initial_velocities;
  std::optional<LaminateSpec> laminate;  // `laminate:` section: meshed by mesh/laminate_mesher
  std::optional<ImpactorSpec> impactor;  // `impactor:` section
  std::vector<RigidBodySpec> rigid_bodies;
  std::vector<RigidWallSpec> rigid_walls;
  std::vector<ContactSpec> contacts;
  Vec3 gravity{0, 0, 0};                 // m/s^2, body-force acceleration on every node (*LOAD_BODY)
  std::optional<CouponSpec> coupon;      // `coupon:` section: fracture-coupon history columns
  // Where each key the loader looked up was given, by key path ("laminate.element_size",
  // "mesh.boxes[0].elements"): checks made after loading point the user at the right line.
  std::map<std::string, SourceLocation> key_locations;

  // The location of `key_path`, or the scene file with the key path when it was not given.
  SourceLocation where_of(const std::string& key_path) const {
    const auto it = key_locations.find(key_path);
    return it != key_locations.end() ? it->second : SourceLocation{file, 0, 0, key_path};
  }
};

}  // namespace plyimpact::config
