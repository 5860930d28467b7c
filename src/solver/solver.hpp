// Central-difference explicit solver with lumped mass (LS-DYNA Theory Manual, "Time Integration"):
//   v^{n+1/2} = v^{n-1/2} + dt^n f^n / m,  dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2
//   x^{n+1}   = x^n + dt^{n+1/2} v^{n+1/2}
//   f^{n+1}   = element pass at x^{n+1} with v^{n+1/2}; dt^{n+3/2} = TSSFAC * min_e dt_e
// Velocity boundary conditions are imposed on v^{n+1/2}; the force they exert (reaction) and its
// work (external work) are recorded. The solver stops with a RunError naming the element, time and
// cause when an element inverts, a value becomes non-finite or the step collapses.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "solver/element_update.hpp"
#include "solver/state.hpp"

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
  // exact at t = 0). ratio = total / (initial total + external work).
  const Energies& balance() const { return state_.last_balance; }
  double energy_ratio() const;

  // Acceleration f/m (0 at massless nodes), for output.
  std::vector<double> acceleration() const;

  // OpenMP threads the cycle actually uses (1 below the size where a parallel pass pays off).
  int threads_used() const;

  // Name of the part that owns element `id` (1-based), for messages.
  std::string part_of_element(Index id) const;

 private:
  void element_pass(double dt);
  void check_after_pass(double dt_used);

  const model::Model& model_;
  State state_;
  std::vector<double> inverse_mass_;       // (num_nodes), 0 at massless nodes
  std::vector<int> dof_constraint_;        // (num_nodes*3) index into model.constraints, -1 free
  std::vector<double> constraint_force_;   // (num constraints) last reaction per dof
  std::vector<double> constraint_work_;    // (num constraints)
  std::vector<double> curve_value_;        // (num curves) value at t^{n+1/2}
  std::vector<ChunkResult> chunk_results_; // (num chunks)
  std::vector<double> node_chunk_ke_;      // (num node chunks) deterministic kinetic-energy sums
  std::vector<std::vector<int>> set_constraints_;  // per constrained set: constraint indices
};

}  // namespace plyimpact::solver
