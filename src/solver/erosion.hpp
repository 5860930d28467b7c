// Element erosion: why an element is deleted, and what deleting it means for the element pass.
// An eroded element carries no stress and no force from then on; the energy it holds stays in the
// totals and is reported as eroded; its mass stays on the nodes. The solver removes it from the
// schedule and the contact surfaces (it reads ChunkResult::eroded).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"
#include "solver/state.hpp"

namespace plyimpact::solver {

// Why an element was eroded (history.csv and summary.json count them per part and cause).
enum class ErosionCause : int {
  PlasticStrain = 1,  // MAT_003 FS / MAT_024 FAIL / MAT_015 damage or spall / MAT_098 PSFAIL
  TimeStep = 2,       // control.erode_tsmin: the element step fell below the limit
  CompositeBase = 10, // MAT_054: 10 + material::CompositeDamageCause
};
const char* erosion_cause_name(int cause);

// Whether any element of the model can be eroded (a material that fails, or control.erode_tsmin):
// the run then books eroded energies and writes their history columns.
bool can_erode(const model::Model& model);

// One element deleted in an element pass: its id, ErosionCause and the internal + hourglass energy
// it held (J), which the run books per part and cause.
struct ErodedElement {
  Index id = 0;
  int cause = 0;
  double energy = 0;
};

// control.erode_tsmin (ERODE/TSMIN): an element whose step fell below the limit is eroded with
// that cause (it replaces a material failure of the same cycle). Not in the initial evaluation.
inline int time_step_erosion(int cause, double erode_tsmin, double dt, double element_dt) {
  if (erode_tsmin > 0 && dt > 0 && element_dt < erode_tsmin) return int(ErosionCause::TimeStep);
  return cause;
}

// Deletes element e (block index; id: its element id) with `points` integration points: zero
// stress; appended to `eroded` with its cause, and the internal + hourglass energy it holds
// (already including this cycle's) added to `eroded_energy`, its hourglass part also to
// `eroded_hourglass` (LS-DYNA's GLSTAT lists the eroded hourglass energy on a line of its own).
//
// What "this cycle's" energy is: only the work of the previous cycle's stress (and hourglass and
// bulk-viscous forces) over this step, half of the trapezoid rule. Central differences pair the
// trapezoid work of a step, (f^n + f^{n+1}) . dx^{n+1/2} / 2, with the kinetic energy that f^n
// and f^{n+1} each give their half steps; an element eroded in the pass that computes f^{n+1}
// never applies that force, so its half f^{n+1} . dx / 2 would be booked without a kinetic
// counterpart: an error per erosion proportional to the step (the test ErosionHourglassEnergy
// measures it).

inline void erode_element(BlockState& st, Index e, Index id, int cause, int points,
                          std::vector<ErodedElement>& eroded, double& eroded_energy,
                          double& eroded_hourglass) {
  std::fill_n(&st.stress[6 * std::size_t(points) * std::size_t(e)], 6 * points, 0.0);
  const double held = st.internal_energy[e] + st.hourglass_energy[e];
  eroded.push_back({id, cause, held});
  eroded_energy += held;
  eroded_hourglass += st.hourglass_energy[e];
}

}  // namespace plyimpact::solver
