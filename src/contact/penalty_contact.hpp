// Penalty contact, node to segment (theory.md section 8): automatic (two-way) surface-to-surface
// contact between two sets of parts, or single-surface contact of one set with itself; both with
// the ERODING_ option (the surface is rebuilt from the exposed faces when elements are deleted).
//   detection : bucket sort of the segments (contact/bucket_grid), re-sorted every BSORT cycles or
//               when a contact node has moved a quarter of the search allowance; closest-point
//               projection (contact/geometry) with MAXPAR; a node penetrates when its gap
//               g = n . (x_s - x_c) - g_0 lies in (-depth, 0) (g_0: initial-penetration offset).
//               Allowance and bucket edge follow the median segment size and each segment's box
//               is expanded by its own margin (graded meshes: a fine zone is not one bucket).
//               Incremental: at each sort every node keeps the segments it can reach before the
//               next one and searches only those; only reachable segments are refreshed.
//   stiffness : SOFT 0  k = min(k_node, k_seg), k_seg = SLSFAC SF K A^2 / V (PENOPT 1)
//               SOFT 1  k = max(SOFT 0 value, SOFSCL 0.5 m* / dt_c^2), m* = min(node, segment mass)
//               SOFT 2  k = 0.5 SLSFAC SF (m1 m2 / (m1 + m2)) / dt_c^2, m = segment masses
//   force     : f_s = (k |g| + viscous) n + f_t on the node, -N_k f_s on the segment nodes, so
//               linear momentum is conserved to round-off. Friction: elastic-slip return map with
//               mu = FD + (FS - FD) exp(-DC |v_rel|); VDC: normal viscous damping, % of critical.
//   energy    : contact energy = - work of the contact forces (trapezoid in time; a spring that
//               engages, switches segment or changes stiffness in the step is booked at its
//               potential 0.5 k g^2: a jump up is energy the discrete model created and shows in
//               the energy ratio, a jump down or a release stays in the contact energy), so it is
//               never below the potential of the active springs; the frictional part (work of
//               the tangential forces against the slip) is reported separately.
//   stability : a priori step of the stiffest single spring (check, warning) and, every pass, the
//               Gershgorin bound of the active springs (spring_stable_step), which the solver
//               combines with the element step.
// Serial and allocation-free per cycle (buffers sized at construction or rebuild), so the result
// does not depend on the thread count.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "contact/bucket_grid.hpp"
#include "core/aligned_allocator.hpp"
#include "contact/geometry.hpp"
#include "contact/surface.hpp"
#include "model/model.hpp"

namespace plyimpact::contact {

struct InitialPenetrations {
  std::size_t count = 0;
  double max_depth = 0;    // m
  bool moved = false;      // true: nodes moved onto the surface; false: kept as offset
};

// Per-contact output of the last pass.
struct ContactForces {
  Vec3 resultant{0, 0, 0};   // N, total contact force on side A (on the surface for single surface: 0)
  double normal = 0;         // N, sum of the normal force magnitudes of all contact points
  double tangential = 0;     // N, sum of the friction force magnitudes
  std::size_t active = 0;    // number of penetrating nodes
  double potential = 0;      // J, sum of 0.5 k g^2 of the active springs (the contact energy is never below it)
};

class PenaltyContact {
 public:
  // dt_initial: the initial solution step (TSSFAC applied), Delta t_c of SOFT 1/2 unless DTSTIF.
  PenaltyContact(const model::Model& model, const model::Contact& def, const std::vector<double>& x,
                 double dt_initial);

  // Detects initial penetrations at x and, as the scene says, moves the penetrating deformable
  // nodes onto the surface or stores the penetration as a zero-force offset.
  InitialPenetrations resolve_initial_penetrations(std::vector<double>& x);

  // Adds the contact forces at x^{n+1} (velocities v^{n+1/2}) to f. dt: Delta t^{n+1/2}, the step
  // that led to x (0 for the initial evaluation).
  void apply(const double* x, const double* v, double* f, double dt);

  // After element deletion: rebuild the surfaces from the active elements at x (eroding contact).
  void rebuild(const AliveMask& alive, const std::vector<double>& x);

  const std::string& name() const { return def_.spec.name; }
  bool eroding() const { return def_.spec.eroding; }
  int soft() const { return def_.spec.SOFT; }
  double energy() const { return energy_; }                  // J, includes friction and damping work
  double friction_energy() const { return friction_energy_; }  // J, dissipated by friction
  const ContactForces& forces() const { return forces_; }
  // Nodes that can carry a contact force and their last forces (num, 3) — for rigid-body output.
  const std::vector<Index>& force_nodes() const { return union_nodes_; }
  const std::vector<double>& node_forces() const { return fc_; }
  std::size_t num_segments() const { return seg_side_.size(); }
  std::size_t num_slave_nodes() const { return sn_node_.size(); }
  double stiffness_min() const { return k_min_; }   // N/m over possible node-segment pairs
  double stiffness_max() const { return k_max_; }
  // A priori stable step of the stiffest single node-segment spring that can form, 2 / omega (no
  // TSSFAC): for `check` and the set-up warning.
  double stable_step() const { return dt_stable_; }
  // Stable step of the springs active in the last pass, 2 / omega with omega^2 the Gershgorin bound
  // of M^-1 K_c (every spring touching a node summed; the solver combines it with the element step).
  // Infinity when no spring is active.
  double spring_stable_step() const { return dt_springs_; }
  long sorts() const { return sorts_; }
  // Nodes found behind a face at the first pass after an eroding rebuild (exposed faces, nodes new
  // to the surface), kept as offsets instead of springs.
  long exposed_offsets() const { return exposures_; }

 private:
  void build(const std::vector<double>& x, const AliveMask* alive);
  // Bucket sort, refresh of every record and normal, candidate lists. step_depth: the largest
  // new-contact depth of the present pass (4 dt v_max), which bounds the lists' depth cap.
  void sort(const double* x, double step_depth);
  // Segments of the same side sharing a node with each segment (nbr_).
  void build_neighbours();
  double stiffness(std::size_t i, std::size_t s) const;
  // Best penetrated segment of slave node i at x, or -1; fills the projection.
  // new_contact_depth: deepest penetration accepted for a node that was not in contact at the last
  // pass (it can only have crossed the surface by its relative motion in one step; a deeper
  // "penetration" is a node beside an edge projecting onto a side face, not a real one).
  // Records and the node's normal are refreshed here when first looked at in a pass.
  // v, dt (optional): velocities and step, for the per-segment bound of what a new contact can
  // have crossed in the step.
  long find_segment(std::size_t i, const double* x, Projection& proj, double new_contact_depth,
                    const double* v = nullptr, double dt = 0);
  void estimate_stiffness_range();
  // Gap offset of slave node i on segment s: the initial-penetration offset plus an exposure offset
  // when s is the segment it was found behind.
  double offset_of(std::size_t i, long s) const { return sn_offset_[i] + (s == sn_exp_seg_[i] ? sn_exp_offset_[i] : 0.0); }
  // Identity of segment s across a rebuild: side and sorted nodes; all -1 for s < 0.
  std::array<Index, 5> segment_key(long s) const;
  // Search data of segment s at x (seg_geo_): bilinear coefficients, bounding sphere, normal bound,
  // in-plane bounds, stamped with the present pass (cycle_).
  void refresh_segment(std::size_t s, const double* x);
  // Every record and node normal (at a sort and before the initial-penetration check).
  void refresh_all(const double* x);
  // Normal of slave node i from its own segments (refreshing them if stale).
  void node_normal(std::size_t i, const double* x);
  // Bounding radius (float, rounded up) and refresh stamp, packed in slot 3 of a record.
  static float segment_radius(const double* g) {
    float r;
    std::memcpy(&r, g + 3, sizeof r);
    return r;
  }
  static std::uint32_t segment_stamp(const double* g) {
    std::uint32_t stamp;
    std::memcpy(&stamp, reinterpret_cast<const char*>(g + 3) + sizeof(float), sizeof stamp);
    return stamp;
  }
  // After a sort: each slave node's candidate list (segments it can reach before the next sort).
  // full_depth: lists for any depth (initial-penetration check), else for the new-contact depth.
  void build_candidates(const double* x, bool full_depth);

  const model::Model& model_;
  model::Contact def_;
  bool single_ = false;
  double dt_c_ = 0;
  SurfaceBuilder builder_a_, builder_b_;
  std::vector<char> node_rigid_;   // (num_nodes) slaved to a rigid body
  // Segments.
  std::vector<Index> seg_nodes_;   // (S, 4)
  std::vector<Index> seg_owner_;   // (S, 8) owning element's nodes (-1 for the impactor surface)
  std::vector<char> seg_side_;     // 0 = A, 1 = B
  std::vector<double> seg_k_;      // SOFT 0 stiffness incl. SLSFAC and SFS/SFM (inf: no element)
  std::vector<double> seg_mass_;   // SOFT 2 segment mass (half the element's)
  std::vector<double> seg_node_mass_;  // mean nodal mass of its nodes
  std::vector<double> seg_depth_;  // release depth, m
  // Hot per-segment record, refreshed every pass, one 128-byte record per segment aligned to 128
  // bytes (a candidate's tests read it contiguously instead of gathering four nodes; the sphere
  // test reads only its first cache line): [0..2] centre c, [3] bounding radius, [4..6] a1,
  // [7] release depth, [8..10] a2, [11] two floats: bound of the unit normal's deviation from the
  // centre normal and 1 / |a1 x a2|, [12..14] a3 (geometry.hpp coefficient form), [15] two floats:
  // in-plane bounds of (p - c) . a1 and (p - c) . a2 for an accepted node (refresh_segment).
  static constexpr std::size_t kGeo = 16;
  AlignedVector<double, 128> seg_geo_;  // (S, kGeo)
  std::vector<Index> seg_local_;   // (S, 4) union index of each segment node
  // Slave nodes.
  std::vector<Index> sn_node_;
  std::vector<char> sn_side_;
  std::vector<double> sn_k_, sn_mass_, sn_seg_mass_;
  std::vector<double> sn_offset_;  // initial-penetration baseline gap (<= 0)
  std::vector<double> sn_ft_;      // (N, 3) tangential (friction) force of the last pass
  std::vector<double> sn_normal_;  // (N, 3) area-weighted outward normal of the node's own surface
  std::vector<long> sn_segment_;   // segment the node was in contact with at the last pass, -1
  std::vector<char> sn_engaged_;   // in contact at the last pass (kept across a rebuild, unlike sn_segment_)
  // The spring of the last pass (kept across a rebuild): gap g (0: none), stiffness k and normal
  // force (N, 3); its potential 0.5 k g^2 is what a segment switch starts from (apply).
  std::vector<double> sn_gap_, sn_k_last_, sn_fn_;
  // Eroding rebuild: sn_new_ / seg_new_ mark nodes and segments the rebuild added; in the pass
  // after it (exposed_pass_) a node without a spring that is found behind one of them gets its
  // gap as an offset on that segment (sn_exp_offset_ <= 0 on sn_exp_seg_, kept across rebuilds,
  // relaxed as the node backs out, cleared when it leaves that segment).
  std::vector<char> sn_new_, seg_new_;
  std::vector<double> sn_exp_offset_;
  std::vector<long> sn_exp_seg_;
  bool exposed_pass_ = false;
  long exposures_ = 0;
  // Incremental search (LS-DYNA-style: between bucket sorts a node only looks at the segments it
  // can reach): candidates of slave node i are cand_[cand_start_[i] .. cand_start_[i + 1]), built
  // at each sort from its bucket, in bucket order.
  std::vector<Index> cand_start_, cand_;
  std::vector<Index> own_start_, own_segs_;  // (CSR over slave nodes) segments of the node's own side
  std::vector<Index> nbr_start_, nbr_;  // (CSR over segments) neighbours sharing a node, same side
  double new_depth_cap_ = 0;       // bound of the new-contact depth until the next sort, m
  double list_allowance_ = 0;      // motion allowed before the next sort (<= allowance_), m
  // Pass counter: a record (or node normal) is refreshed when first looked at in a pass, so
  // segments no node comes near cost nothing (starts at 1: zeroed records are stale).
  std::uint32_t cycle_ = 1;
  // Nodes receiving forces (union of both sides), their forces and positions at the last sort.
  std::vector<Index> union_nodes_;
  std::vector<Index> local_of_;    // (num_nodes) -> index in union_nodes_, -1
  std::vector<char> union_side_a_;
  std::vector<double> fc_, fc_prev_, x_sort_;
  std::vector<double> union_inv_mass_;  // 1 / m of deformable nodes, 0 for rigid or massless ones
  std::vector<double> union_row_;       // Gershgorin row sums of the last pass's springs (zeroed after use)
  std::vector<Index> sn_local_;    // slave node -> union index
  BucketGrid grid_[2];                  // per side (single surface: [0] only)
  std::vector<Index> side_segs_[2];     // grid item -> segment
  std::vector<double> boxes_[2];
  std::vector<double> seg_margin_; // (S) search margin of each segment's box, m
  double cell_ = 0, allowance_ = 0, search_cell_ = 0;  // median extent, allowance, bucket edge
  long cycles_since_sort_ = 0, sorts_ = 0;
  double energy_ = 0, friction_energy_ = 0;
  ContactForces forces_;
  double k_min_ = 0, k_max_ = 0, dt_stable_ = std::numeric_limits<double>::infinity();
  double dt_springs_ = std::numeric_limits<double>::infinity();
};

}  // namespace plyimpact::contact
