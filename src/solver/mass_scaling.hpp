// Mass scaling as LS-DYNA's *CONTROL_TIMESTEP DT2MS < 0 (docs/theory.md, "Mass scaling"): every
// deformable element whose stable step dt_e is below the target |DT2MS| gets the mass
// dm_e = m_e ((|DT2MS| / dt_e)^2 - 1), m_e = rho V0, spread over its 8 nodes as its own lumped mass
// is, so that its step becomes |DT2MS| (the run's step is then TSSFAC |DT2MS| unless a spring is
// stiffer). The mass is added once, at the reference geometry, before the run (LS-DYNA's MS1ST = 1):
// the model carries it, so a restart rebuilds exactly the same masses and every thread count sees
// the same arrays; an element that distorts later may still lower the step (ERODE/TSMIN, TFAIL and
// the step-collapse stop keep seeing it).
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"

namespace plyimpact::solver {

class Solver;

// Warning above this added fraction of a part's mass: 5 %, the usual limit of LS-DYNA practice for
// dynamic runs at part level (docs/theory.md, "Mass scaling").
inline constexpr double kAddedMassWarnFraction = 0.05;

// Applies control.dt2ms to the model once: adds the mass to model.mass (rigid-body nodes excepted:
// they move with their body), sets each scaled block's step_scale = |DT2MS| / dt_e (1 elsewhere)
// and fills model.mass_scaling. No change when dt2ms is 0. Throws InputError when the added mass
// exceeds control.endmas percent of the model's mass (*CONTROL_TERMINATION ENDMAS). Idempotent.
void apply_mass_scaling(model::Model& model);

// `check` lines: the target, the added mass per part and in total, and which springs (contacts,
// tiebreaks, cohesive interfaces) still bound the step below the target.
std::vector<std::string> mass_scaling_lines(const Solver& solver);

}  // namespace plyimpact::solver
