// Force contributors: everything besides the elements that adds nodal forces (gravity, rigid walls,
// penalty contact, rigid-body coupling, interfaces) sits behind this interface, so the solver's
// cycle loops over a list instead of naming each source. A contributor
//   - adds its forces at x^{n+1} (velocities v^{n+1/2}) in one of two phases: Forces (before the
//     next step is known: penalty springs, body forces) or Constraints (kinematic conditions that
//     predict the next position and so need dt^{n+3/2}: rigid walls), and after both, Bookkeeping
//     (reads what the others applied: the rigid bodies' contact force);
//   - names its energies (key in summary.json, column in history.csv, counted in the total or not)
//     and any external work it does;
//   - bounds the stable step (infinity when it has no stiffness); the solver combines the bound
//     with the element step (Solver::combined_step);
//   - reacts to erosion (alive mask and x), and names the nodes it still acts on, so the solver
//     keeps them when erosion leaves them without elements (mark_held_nodes);
//   - says whether it is active and why (one line of `check` and summary.json subsystems);
//   - has history columns of its own and its run state (visit_state).
#pragma once

#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/state_visitor.hpp"
#include "core/types.hpp"
#include "model/model.hpp"
#include "model/subsystems.hpp"

namespace plyimpact::solver {

// Per (block) element alive flags; an empty vector means every element of the block is alive.
using AliveMask = std::vector<std::vector<char>>;

struct ForceContext {
  const double* x = nullptr;     // (num_nodes, 3) x^{n+1}
  const double* v = nullptr;     // (num_nodes, 3) v^{n+1/2}
  double* f = nullptr;           // (num_nodes, 3) f^{n+1}: contributors add to it
  const double* mass = nullptr;  // (num_nodes) lumped mass, kg (rigid-body nodes keep theirs)
  double time = 0;               // t^{n+1}, s
  double dt = 0;                 // Delta t^{n+1/2}, the step that led to x (0 at the initial evaluation)
  double dt_n1 = 0;              // Delta t^{n+1} = (Delta t^{n+1/2} + Delta t^{n+3/2}) / 2 (Constraints phase)
  double dt_next = 0;            // Delta t^{n+3/2} with every stable-step bound applied (Constraints phase)
};

// One named energy of the balance, J. in_total: part of the total energy (stored or dissipated by
// the model); a part of another energy shown on its own (friction within contact) is not.
struct EnergyName {
  std::string key;     // summary.json final_energies key
  std::string column;  // history.csv column
  bool in_total = true;
};

// Nodes a contributor acts on and its last forces on them (num, 3): the rigid bodies' contact force.
struct NodeForces {
  const std::vector<Index>* nodes = nullptr;
  const std::vector<double>* forces = nullptr;
  // Optional: the entries (ascending) outside which every force is zero, so a sum need not visit
  // the others (skipping a zero leaves a sum's bits as they are).
  const std::vector<Index>* loaded = nullptr;
};

class ForceContributor {
 public:
  enum class Phase { Forces, Constraints, Bookkeeping };

  virtual ~ForceContributor() = default;
  virtual std::string name() const = 0;
  virtual Phase phase() const { return Phase::Forces; }
  virtual void apply(const ForceContext& context) = 0;

  virtual std::vector<EnergyName> energy_names() const { return {}; }
  // Values in the order of energy_names, at the last apply.
  virtual void energies(std::span<double> out) const { (void)out; }
  // Work done on the model up to the last apply (counted in the external work), J.
  virtual double external_work() const { return 0.0; }

  // Stable step of its stiffness after the last apply (no TSSFAC), s; infinity when none.
  virtual double stable_step() const { return std::numeric_limits<double>::infinity(); }
  // A diagnosis found while setting up (e.g. its stiffness controls the step); empty when none.
  virtual std::vector<std::string> warnings() const { return {}; }

  virtual void on_erosion(const AliveMask& alive, const std::vector<double>& x) {
    (void)alive;
    (void)x;
  }

  // Sets held[node] = 1 for every node this contributor may still put a force on (its live springs,
  // pairs, ties, cohesive elements, wall nodes). After an erosion the solver removes from the
  // calculation the nodes that no live element and no contributor holds (Solver::remove_freed_nodes),
  // so a contributor that acts on particular nodes must name them here. Body forces (gravity) hold
  // nothing: a removed node is out of the calculation, as LS-DYNA's ENMASS 0 removes it.
  virtual void mark_held_nodes(std::vector<char>& held) const { (void)held; }

  // Contact forces (appended, one entry per surface) that the rigid bodies report as their contact force.
  virtual void node_forces(std::vector<NodeForces>& out) const { (void)out; }

  virtual std::vector<std::string> history_columns() const { return {}; }
  virtual void history_values(std::vector<double>& row) const { (void)row; }

  virtual void visit_state(StateVisitor& visitor) { (void)visitor; }
};

// Stable step of the elements and a contributor's springs together, no TSSFAC (solver.cpp says why).
double combined_step(double dt_element, double dt_springs);

}  // namespace plyimpact::solver
