// Central-difference explicit solver with lumped mass (LS-DYNA Theory Manual, "Time Integration"):
//   v^{n+1/2} = v^{n-1/2} + dt^n f^n / m,  dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2
//   x^{n+1}   = x^n + dt^{n+1/2} v^{n+1/2}
//   f^{n+1}   = element pass at x^{n+1} with v^{n+1/2}, then the force contributors
//   dt^{n+3/2} = TSSFAC combined_step(min_e dt_e, min over the contributors' bounds)
// Velocity boundary conditions are imposed on v^{n+1/2}; the force they exert (reaction) and its
// work (external work) are recorded. Everything else that adds nodal forces (gravity, penalty
// contact, rigid walls, the rigid-body coupling; solver/contributors.hpp) is a ForceContributor,
// applied in its phase after the element pass; rigid bodies (solver/rigid_body) are integrated in
// the node update from the forces of their slaved nodes. The solver stops with a RunError naming
// the element, time and cause when an element inverts, a value becomes non-finite or the step
// collapses.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "solver/chunk_plan.hpp"
#include "solver/element_update.hpp"
#include "solver/force_contributor.hpp"
#include "solver/node_chunk_owners.hpp"
#include "solver/penalty_contacts.hpp"
#include "solver/rigid_body.hpp"
#include "solver/rigid_walls.hpp"
#include "solver/state.hpp"
#include "solver/thread_choice.hpp"

namespace plyimpact::solver {

class Solver {
 public:
  // Allocates the state, sets initial velocities and evaluates the initial forces and stable step.
  explicit Solver(const model::Model& model);

  // Advances one cycle. Throws RunError with a diagnosis when the run cannot go on.
  void step();

  const State& state() const { return state_; }
  State& state() { return state_; }
  const model::Model& model() const { return model_; }

  // Energy balance at the current time t^n (kinetic energy from v^{n-1/2}, v^{n+1/2} averaged,
  // exact at t = 0), the integrator's terms and the contributors'. ratio = total / (initial total
  // + external work).
  const Energies& balance() const { return state_.last_balance; }
  double energy_ratio() const;

  // Acceleration f/m (0 at massless nodes), for output.
  std::vector<double> acceleration() const;

  // False once element e of block b has been deleted (eroded).
  bool element_alive(int block, Index e) const { return alive_[block].empty() || alive_[block][e] != 0; }

  // OpenMP threads the cycle actually uses (1 below the size where a parallel pass pays off).
  int threads_used() const;
  // Let the solver pick one or all OpenMP threads by timing both now and then (ThreadChoice); for
  // runs whose thread count the user left open. Off by default: the current count is used.
  void choose_threads_by_timing(bool on) { thread_choice_.enable(on && parallel_); }
  // How often the parallel element pass's chunk plan is reviewed (every `passes` parallel passes)
  // and how much shorter a new plan's simulated pass must be to replace it (solver/chunk_plan.hpp).
  // The defaults suit runs; tests shorten them to exercise re-planning.
  void set_chunk_plan_review(long passes, double min_gain) {
    replan_passes_ = passes;
    replan_gain_ = min_gain;
  }

  // Wall seconds spent in each part of the cycle since construction (profiling; a few clock reads
  // per cycle). Names: "node update", "element pass", "element checks" (sums, erosion, crashfront)
  // and each contributor's name().
  struct PhaseTime {
    std::string name;
    double seconds = 0;
  };
  const std::vector<PhaseTime>& phase_times() const { return phase_times_; }

  // Name of the part that owns element `id` (1-based), for messages.
  std::string part_of_element(Index id) const;

  // Everything the run needs to continue: the state, the integrator's own accumulators, alive masks,
  // rigid bodies and every contributor's state. A solver built from the same model and given the
  // state read back continues exactly as the one that wrote it.
  void visit_state(StateVisitor& visitor);

  // Deletes elements (1-based ids) from the next cycle on: they no longer carry stress, their
  // energies stay in the totals (eroded), and eroding contacts rebuild their surfaces at once. Their
  // nodes that nothing holds any more leave the calculation (remove_freed_nodes).
  void delete_elements(const std::vector<Index>& ids);

  // The active force contributors, in the order they are applied.
  const std::vector<std::unique_ptr<ForceContributor>>& contributors() const { return contributors_; }
  // Views of particular contributors for output and `check` (empty when the scene has none).
  const std::vector<contact::PenaltyContact>& contacts() const;
  const std::vector<contact::RigidWallConstraint>& rigid_walls() const;
  const std::vector<RigidBodyState>& rigid_bodies() const;
  // Initial penetrations found at t = 0, one per contact (for `check`).
  const std::vector<contact::InitialPenetrations>& initial_penetrations() const;
  // For an element inverted in the first cycles: what the contacts' set-up moved (empty if nothing).
  std::string moved_nodes_note() const;
  // Diagnoses found while setting up (e.g. the contact step controls the time step).
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  void element_pass(double dt);
  // Before a parallel element pass on `threads` threads: a chunk plan for them, reviewed from the
  // measured chunk times every replan_passes_ parallel passes (set_chunk_plan_review).
  void keep_chunk_plan(int threads);
  void check_after_pass(double dt_used);
  void count_erosion(const ErodedElement& el);
  // Alive ranges of every chunk from alive_ (after a deletion or reading a state).
  void update_chunk_ranges();
  void mark_crashfront(const std::vector<Index>& eroded);
  // node_elements_ (node -> (block, element)), built at the first erosion.
  void build_node_adjacency();
  // After a deletion (deleted: (block, element) of each deleted element): the nodes of those
  // elements that no live deformable element, no contributor (mark_held_nodes), no constraint and no
  // rigid body holds leave the calculation. Their velocity is zeroed and their inverse mass set to 0,
  // so they stay where they are, and their kinetic energy is booked as eroded kinetic energy. As
  // LS-DYNA's ENMASS 0 (the eroding contact's default) removes a node left without elements; an
  // ENMASS 1 contact holds such nodes, and they stay. Nothing acts on a removed node, and it acts on
  // nothing, so its removal changes no force: it only stops a mass point drifting on for ever with
  // kinetic energy that is no longer the structure's (freed_nodes.cpp).
  void remove_freed_nodes(const std::vector<std::pair<int, Index>>& deleted);
  // inverse_mass_ zero at the removed nodes (after reading a state).
  void apply_removed_nodes();
  // Builds the active contributors (after the initial element pass) and the balance's term list.
  void build_contributors();
  // The contributors' forces at x^{n+1}, phase by phase; dt = Delta t^{n+1/2} (0 at t = 0).
  void contributor_forces(double dt);
  // After the Forces phase: state_.dt_contact from the contributors' bounds (0 = none) and
  // dt_next_half = TSSFAC combined_step(element step, that bound).
  void update_step_bounds();
  // The balance at t^n: the integrator's terms and the contributors' (values of their last apply).
  void record_balance(double kinetic, double external_work);

  const model::Model& model_;
  State state_;
  std::vector<double> inverse_mass_;       // (num_nodes), 0 at massless nodes
  std::vector<int> dof_constraint_;        // (num_nodes*3) index into model.constraints, -1 free
  std::vector<double> constraint_force_;   // (num constraints) last reaction per dof
  std::vector<double> constraint_work_;    // (num constraints)
  std::vector<double> curve_value_;        // (num curves) value at t^{n+1/2}
  std::vector<ChunkResult> chunk_results_; // (num chunks)
  bool parallel_ = false;                  // the model is large enough for the parallel passes
  // Parallel element pass: which thread runs which chunks in which order, the wall time each chunk
  // took since the plan was last reviewed, and the number of the last pass each chunk has finished.
  ChunkPlan chunk_plan_;
  std::vector<double> chunk_seconds_;
  long passes_since_plan_ = 0;
  long replan_passes_;
  double replan_gain_;
  std::vector<std::uint64_t> chunk_done_;
  std::uint64_t element_passes_ = 0;
  std::vector<double> node_chunk_ke_;      // (num node chunks) deterministic kinetic-energy sums
  std::vector<std::vector<int>> set_constraints_;  // per constrained set: constraint indices
  std::vector<double> node_mass_;          // (num_nodes) lumped mass, 0 at rigid-body nodes (their body moves them)
  std::vector<int> node_body_;             // (num_nodes) rigid body index, -1
  std::vector<Index> rigid_nodes_;         // nodes of the rigid bodies (their force outlives the node update)
  NodeChunkOwners node_owners_;            // which thread updates which node chunk
  std::unique_ptr<RigidBodies> rigid_;     // null without rigid bodies
  std::vector<std::unique_ptr<ForceContributor>> contributors_;
  const PenaltyContacts* contacts_ = nullptr;  // views into contributors_ (null when absent)
  const RigidWalls* walls_ = nullptr;
  std::vector<std::size_t> energy_counts_;  // (num contributors) energies each reports
  std::vector<double> energy_scratch_;     // (max energies of one contributor)
  std::vector<std::string> warnings_;
  std::vector<PhaseTime> phase_times_;
  ThreadChoice thread_choice_;  // kNodeUpdate, kElementPass, kElementChecks, then per contributor
  double dt_element_crit_ = 0;              // s, element stable step of the last pass (no TSSFAC)
  // Element deletion: alive[b][e] (empty vector = all alive) and, per chunk, its alive ranges.
  contact::AliveMask alive_;
  std::vector<std::vector<std::pair<Index, Index>>> chunk_ranges_;  // empty = whole chunk
  std::vector<Index> node_elements_start_;               // CSR over nodes (built at the first erosion)
  std::vector<std::pair<int, Index>> node_elements_;     // (block, element) touching each node
  bool contributors_built_ = false;                       // build_contributors has run
  std::vector<char> held_scratch_;                       // (num_nodes) remove_freed_nodes' marks
  std::size_t eroded_kinetic_term_ = 0;                  // its index in the balance's terms
};

}  // namespace plyimpact::solver
