#include "solver/state.hpp"

#include <string>

namespace plyimpact::solver {

void BlockState::visit_state(StateVisitor& sv) {
  sv.fixed_array("stress", stress);
  sv.fixed_array("hourglass", hourglass);
  sv.fixed_array("hourglass_moduli", hourglass_moduli);
  sv.fixed_array("step_wave_speed", step_wave_speed);
  sv.fixed_array("bulk_q", bulk_q);
  sv.fixed_array("step_q", step_q);
  sv.fixed_array("internal_energy", internal_energy);
  sv.fixed_array("hourglass_energy", hourglass_energy);
  sv.fixed_array("volume", volume);
  sv.fixed_array("history", history);
  sv.fixed_array("axes", axes);
  sv.fixed_array("initial_dt", initial_dt);
  sv.fixed_array("erosion_strain_0", erosion_strain[0]);
  sv.fixed_array("erosion_strain_1", erosion_strain[1]);
}

void State::visit_state(StateVisitor& sv) {
  StateGroup group(sv, "state");
  sv.scalar("time", time);
  sv.scalar("cycle", cycle);
  sv.scalar("dt_prev_half", dt_prev_half);
  sv.scalar("dt_next_half", dt_next_half);
  sv.scalar("dt_initial", dt_initial);
  sv.scalar("dt_element", dt_element);
  sv.fixed_array("x", x);
  sv.fixed_array("v", v);
  sv.fixed_array("f", f);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    StateGroup block(sv, "block " + std::to_string(b));
    blocks[b].visit_state(sv);
  }
  sv.scalar("internal_energy", internal_energy);
  sv.scalar("hourglass_energy", hourglass_energy);
  sv.scalar("bulk_viscous_energy", bulk_viscous_energy);
  sv.scalar("external_work", external_work);
  sv.scalar("dt_contact", dt_contact);
  sv.scalar("dt_contact_controls", dt_contact_controls);
  sv.scalar("initial_total_energy", initial_total_energy);
  {
    StateGroup balance(sv, "balance");
    sv.scalar("time", last_balance.time);
    for (auto& t : last_balance.terms) sv.scalar(t.key, t.value);
  }
  sv.fixed_array("reaction", reaction);
  sv.scalar("eroded_elements", eroded_elements);
  sv.scalar("eroded_energy", eroded_energy);
  sv.scalar("eroded_hourglass_energy", eroded_hourglass_energy);
  sv.array("erosion", erosion);
  sv.array("removed_nodes", removed_nodes);
  sv.scalar("eroded_kinetic_energy", eroded_kinetic_energy);
}

}  // namespace plyimpact::solver
