// Penalty contact, node to segment (docs/theory.md section 10): automatic (two-way) surface-to-surface
// contact between two sets of parts, or single-surface contact of one set with itself; both with
// the ERODING_ option (the surface is rebuilt from the exposed faces when elements are deleted).
// Orchestration over the contact toolkit:
//   segments  : contact/segment_set (assembly, identity across an eroding rebuild)
//   search    : contact/segment_search (buckets, candidate lists, records, projection) and
//               contact/catch_rules (which segment a node penetrates, with the spring history of
//               contact/spring_history)
//   law       : contact/penalty_law (SOFT 0/1/2 stiffness, normal force with VDC, friction)
// and, here, what ties them together:
//   force     : f_s = (k |g| + viscous) n + f_t on the node, -N_k f_s on the segment nodes, so
//               linear momentum is conserved to round-off.
//   energy    : contact energy = potential of the springs active now (sum 0.5 k g^2) + what friction
//               and damping (VDC) have dissipated + the potential of springs that ended because
//               their node or segment eroded (kept, as an eroded element's energy is); any other
//               spring released, switched or created in a step takes its potential with it, so
//               after separation the contact energy is the dissipation alone, and energy the
//               discrete contact created or lost (a node caught deep, a node released behind the
//               face) shows in the energy ratio instead of being kept in the contact energy.
//               Beside it, the work of the contact forces on the bodies
//               (weighted as the integrator applies them, book_work) gives the energy the contact
//               took from the bodies; created() = energy() - taken() is the energy the discrete
//               contact model created (> 0) or destroyed (< 0), for the run checks.
//   stability : a priori step of the stiffest single spring (check, warning) and, every pass, the
//               Gershgorin bound of the active springs (spring_stable_step), which the solver
//               combines with the element step.
// Threads: the search and law run per contact node in parallel (fixed chunks of nodes, any
// schedule: each node writes only its own history and its outcome slot); the scatter into the
// forces, the stability rows, the sums and the penetration records then follow serially in node
// order, the order of a one-thread pass, so the result is bit-identical for any thread count.
// Allocation-free per cycle (buffers sized at construction or rebuild).
#pragma once

#include <cstdint>

#include <limits>
#include <string>
#include <vector>

#include "contact/geometry.hpp"
#include "contact/penalty_law.hpp"
#include "contact/segment_search.hpp"
#include "contact/segment_set.hpp"
#include "contact/spring_history.hpp"
#include "contact/stiffness_bounds.hpp"
#include "contact/surface.hpp"
#include "core/state_visitor.hpp"
#include "model/model.hpp"

namespace plyimpact::contact {

struct InitialPenetrations {
  std::size_t count = 0;
  double max_depth = 0;    // m
  bool moved = false;      // true: nodes moved onto the surface; false: kept as offset
};

// A node that passed through the surface: released while still behind the face of its last
// segment (deeper than the release depth, or pushed through), as LS-DYNA reports the penetrations
// it releases.
struct PenetrationEvent {
  double time = 0;     // s, of the pass that released it
  double depth = 0;    // m, behind the face at release
  Index node = -1;     // model node index (0-based)
  std::int32_t unused = 0;  // the padding made a member: a restart dump holds defined bytes only
};
struct Penetrations {
  long count = 0;
  PenetrationEvent first, deepest, last;
  double released_potential = 0;  // J, what their springs held at the pass before: gone from the balance
};

// Per-contact output of the last pass.
struct ContactForces {
  Vec3 resultant{0, 0, 0};   // N, total contact force on side A (on the surface for single surface: 0)
  double normal = 0;         // N, sum of the normal force magnitudes of all contact points
  double tangential = 0;     // N, sum of the friction force magnitudes
  std::size_t active = 0;    // number of penetrating nodes
  double potential = 0;      // J, sum of 0.5 k g^2 of the active springs
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
  // that led to x (0 for the initial evaluation); time: t^{n+1} (for the penetration records).
  void apply(const double* x, const double* v, double* f, double dt, double time = 0);

  // Leaves out the node-segment pairs a tiebreak holds (contact/bonded_interfaces); before
  // resolve_initial_penetrations. Not owned.
  void exclude_bonded(const BondedInterfaces* rule) { set_.exclude_bonded(rule); }

  // After element deletion: rebuild the surfaces from the active elements at x (eroding contact).
  void rebuild(const AliveMask& alive, const std::vector<double>& x);

  const std::string& name() const { return def_.spec.name; }
  bool eroding() const { return def_.spec.eroding; }
  int soft() const { return def_.spec.SOFT; }
  double energy() const { return energy_; }  // J, spring potential + friction + damping + eroded springs
  // J, potential of the springs an eroding rebuild ended (their node or segment eroded), part of
  // energy(): it stays in the balance as an eroded element's energy does.
  double eroded_spring_energy() const { return eroded_spring_energy_; }
  double friction_energy() const { return friction_energy_; }  // J, dissipated by friction (part of energy())
  double damping_energy() const { return damping_energy_; }    // J, dissipated by VDC (part of energy())
  double taken() const { return taken_; }  // J, net work the bodies did against the contact forces
  double created() const { return energy_ - taken_; }  // J, energy the discrete contact created (< 0: lost)
  const ContactForces& forces() const { return forces_; }
  // Nodes released while behind the face they were in contact with, since the start.
  const Penetrations& penetrations() const { return penetrations_; }
  // Nodes that can carry a contact force and their last forces (num, 3) — for rigid-body output.
  const std::vector<Index>& force_nodes() const { return set_.force_nodes(); }
  const std::vector<double>& node_forces() const { return fc_; }
  // The force nodes with a force in the last pass, ascending: every other entry of node_forces()
  // is zero.
  const std::vector<Index>& loaded_force_nodes() const { return touched_; }
  std::size_t num_segments() const { return set_.num_segments(); }
  // For check's compliance estimate (contact_compliance).
  const model::Contact& definition() const { return def_; }
  const SegmentSet& segments() const { return set_; }
  const PenaltyLaw& law() const { return law_; }
  std::size_t num_slave_nodes() const { return set_.num_nodes(); }
  double stiffness_min() const { return bounds_.k_min; }   // N/m over possible node-segment pairs
  double stiffness_max() const { return bounds_.k_max; }
  // A priori stable step of the stiffest single node-segment spring that can form, 2 / omega (no
  // TSSFAC): for `check` and the set-up warning.
  double stable_step() const { return bounds_.dt_stable; }
  // Stable step of the springs active in the last pass, 2 / omega with omega^2 the Gershgorin bound
  // of M^-1 K_c (every spring touching a node summed; the solver combines it with the element step).
  // Infinity when no spring is active.
  double spring_stable_step() const { return dt_springs_; }
  long sorts() const { return search_.sorts(); }
  // Nodes found behind a face at the first pass after an eroding rebuild (exposed faces, nodes new
  // to the surface), kept as offsets instead of springs.
  long exposed_offsets() const { return exposures_; }

  // The run state (segment set after rebuilds, search, springs, forces of the last pass, energies):
  // a contact built from the same model and definition that reads it back continues bit-identically.
  void visit_state(StateVisitor& visitor);

 private:
  // After the segment set was (re)assembled at x: search reset and sort, forces and bounds sized.
  void start(const std::vector<double>& x);
  // Books the work of the contact forces on the bodies: power_old = f^{last pass} . v, power_new =
  // f^{this pass} . v (v = v^{n+1/2}), dt = dt^{n+1/2}.
  void book_work(double power_old, double power_new, double dt);
  // What the pass found for one contact node, for the ordered scatter after the parallel loop:
  // a spring on segment s, or (s = -1) a node released while still behind its face.
  struct NodeOutcome {
    std::size_t i = 0;
    long s = -1;
    double N[4] = {0, 0, 0, 0};  // shape functions of the contact point
    double F[3] = {0, 0, 0};     // N, force on the node (normal + friction)
    double k = 0, sum_b = 0;     // stiffness and the Gershgorin factor (apply)
    double fn = 0, potential = 0, tangential = 0, friction_work = 0, damping_work = 0;
    double depth = 0;            // m, released node behind the face
    bool exposure = false;       // an exposure offset was booked
  };
  // Search, law and history of contact node i; fills `out` and returns true when the node has a
  // spring or a penetration to record.
  bool evaluate_node(std::size_t i, const double* x, const double* v, double dt, double v_max, bool friction,
                     NodeOutcome& out);
  // Node i, in contact with segment `last` at the last pass, is released now: how deep it still is
  // behind that face (projecting onto it), 0 when it is not (a penetration otherwise).
  double release_depth(std::size_t i, long last, const double* x);
  // Exposure offsets (spring_history) of node i found on segment s (last: its segment of the last
  // pass); true when one was booked.
  bool update_exposure(std::size_t i, long s, long last, const Projection& pr);

  const model::Model& model_;
  model::Contact def_;
  PenaltyLaw law_;
  SegmentSet set_;
  SegmentSearch search_;
  SpringHistory springs_;
  // Forces on the force nodes (U, 3) of this pass (kept for output) and of the last one (the
  // trapezoid of the contact work).
  std::vector<double> fc_, fc_prev_;
  std::vector<double> rows_;  // (U) Gershgorin row sums of the pass's springs, zeroed after use
  // The force nodes that can have a non-zero entry in fc_ / fc_prev_, ascending: the sums over them
  // are those over every force node (the others add zeros), without walking all of them each pass.
  std::vector<Index> touched_, touched_prev_;
  std::vector<char> marked_;  // (U) scratch: in touched_ during the outcome loop
  void touch(Index u) {
    if (!marked_[std::size_t(u)]) marked_[std::size_t(u)] = 1, touched_.push_back(u);
  }
  // marked_, outcomes_ and outcome_count_ for the present surface (after a restart read one).
  void size_pass_scratch();
  // touched_prev_ from fc_prev_ (after a rebuild renumbered the force nodes).
  void list_previous_forces();
  // Outcomes of the parallel node loop: chunk c of kNodeChunk nodes writes from c kNodeChunk on.
  static constexpr std::size_t kNodeChunk = 256;
  std::vector<NodeOutcome> outcomes_;        // (N) slots
  std::vector<std::size_t> outcome_count_;   // (num chunks)
  long exposures_ = 0;
  double energy_ = 0, friction_energy_ = 0, damping_energy_ = 0, eroded_spring_energy_ = 0;
  double taken_ = 0;       // J, book_work
  double work_power_ = 0;  // W, f . v of the last pass, and its step: the first half of its work
  double work_dt_ = 0;     // s   is corrected at the next pass (book_work)
  ContactForces forces_;
  Penetrations penetrations_;
  StiffnessBounds bounds_;
  double dt_springs_ = std::numeric_limits<double>::infinity();
};

}  // namespace plyimpact::contact
