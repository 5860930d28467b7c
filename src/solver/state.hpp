// State: everything that changes during a run — nodal kinematics, element stresses and hourglass
// forces, energies, time and step sizes. Plain contiguous arrays (structure of arrays), so a state
// can be written to and read back from a restart file and split by a domain decomposition later.
// Time levels: x, time at t^n; v at t^{n-1/2} before a step and t^{n+1/2} after it.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "core/state_visitor.hpp"
#include "core/types.hpp"
#include "solver/energies.hpp"

namespace plyimpact::solver {

struct BlockState {
  std::vector<double> stress;            // (num_elements * points, 6) Cauchy, global axes, xx yy zz xy yz zx
  // (num_elements, 12) hourglass forces Q[i*4+alpha]: accumulated (IHQ 4, 5; global axes i),
  // accumulated in the co-rotational element frame (IHQ 6; element axes i) or last viscous (IHQ 1-3);
  // the viscous ones are kept so their work is booked with the trapezoid rule.
  std::vector<double> hourglass;
  // Hourglass moduli (solver/assumed_strain_hourglass): (num_elements) IHQ 4/5, (num_elements, 6) IHQ 6
  // E_x', E_y', E_z', G_x'y', G_y'z', G_z'x'; empty otherwise.
  std::vector<double> hourglass_moduli;
  // (num_elements) wave speed of the stable step, m/s (solver/directional_step); empty: the material's.
  std::vector<double> step_wave_speed;
  std::vector<double> bulk_q;            // (num_elements) last bulk-viscosity pressure q, Pa (trapezoid work)
  std::vector<double> step_q;            // (num_elements) Q held for the stable step, m/s (element_update step_q)
  std::vector<double> internal_energy;   // (num_elements) J, stress work incl. nothing of q
  std::vector<double> hourglass_energy;  // (num_elements) J
  std::vector<double> volume;            // (num_elements) current volume, m^3 (updated every cycle)
  // Materials with history (MAT_003/024, MAT_054): (num_elements * points, history size), layout
  // documented by the material (material/plasticity.hpp, material/composite_damage.hpp).
  std::vector<double> history;
  std::vector<double> axes;        // (num_elements, 9) current material axes (rows a, b, c), MAT_054
  std::vector<double> initial_dt;  // (num_elements) element step at t = 0 (TFAIL ratio), MAT_054
  // *MAT_054 with erosion neighbourhoods (model::ErosionNeighbours): (num_elements,
  // material::kErosionStrainStride) element-mean strains in material axes and whether they passed a
  // card limit; a pass reads erosion_strain[erosion_strain_read] (the previous pass's)
  // and writes the other. The solver sets the index from the cycle's parity before each pass (so it
  // is not part of the dumped state). Empty otherwise.
  std::vector<double> erosion_strain[2];
  int erosion_strain_read = 0;

  void visit_state(StateVisitor& visitor);
};

// Eroded elements of one part for one cause (ErosionCause), for history.csv and summary.json.
struct ErosionCount {
  int part = 0;
  int cause = 0;
  long count = 0;
  double energy = 0;  // J, the internal + hourglass energy these elements held when deleted
};

struct State {
  double time = 0;
  long cycle = 0;
  double dt_prev_half = 0;   // Delta t^{n-1/2}
  double dt_next_half = 0;   // Delta t^{n+1/2} (stable step for the coming cycle, TSSFAC applied)
  double dt_initial = 0;     // first stable step, reference for the collapse check
  Index dt_element = -1;     // id of the element controlling dt_next_half
  std::vector<double> x, v, f;  // (num_nodes, 3)
  std::vector<BlockState> blocks;
  // Cumulative energies (internal/hourglass/bulk at t^n, after the last element pass).
  double internal_energy = 0, hourglass_energy = 0, bulk_viscous_energy = 0, external_work = 0;
  double dt_contact = 0;           // smallest stable-step bound of the force contributors (no TSSFAC); 0 = none
  bool dt_contact_controls = false;  // a contributor's frequency exceeds the elements' (it dominates the step)
  double initial_total_energy = 0;
  Energies last_balance;           // the balance at the start of the last step (t^n)
  std::vector<double> reaction;    // (num constrained sets, 3) constraint force resultant, N
  // Erosion: elements deleted by their material (or the time-step limit) so far, and the internal
  // plus hourglass energy they held (it stays in the totals; reported as eroded).
  long eroded_elements = 0;
  double eroded_energy = 0;
  double eroded_hourglass_energy = 0;  // J, the hourglass part of eroded_energy
  std::vector<ErosionCount> erosion;
  // Nodes erosion left with nothing acting on them, removed from the calculation
  // (Solver::remove_freed_nodes): (num_nodes) flags, empty until the first removal, and the kinetic
  // energy they carried when removed (J, in the total, as GLSTAT's eroded kinetic energy).
  std::vector<char> removed_nodes;
  double eroded_kinetic_energy = 0;
  long removed_node_count() const { return long(std::count(removed_nodes.begin(), removed_nodes.end(), 1)); }

  // Every member above (the balance by its values: its terms are fixed by the model).
  void visit_state(StateVisitor& visitor);
};

}  // namespace plyimpact::solver
