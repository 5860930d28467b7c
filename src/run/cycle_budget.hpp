// The cycle count a run needs, estimated before it starts: termination time over the initial
// stable step of the elements (LS-DYNA's L / c with L = volume / largest face area, times TSSFAC,
// on the reference geometry). A run estimated beyond control.cycle_limit (default kDefaultCycleLimit)
// is refused at the key that makes it so, instead of starting a run that could never finish (a
// density of 1e-300 asked for 1e147 cycles). Contacts can only shorten the step further, so the
// estimate is a lower bound of the real count.
#pragma once

#include <string>

#include "config/scene.hpp"
#include "model/model.hpp"

namespace plyimpact::run {

inline constexpr double kDefaultCycleLimit = 1e8;

struct CycleEstimate {
  double dt = 0;           // s, initial element step with TSSFAC (infinite with no deformable element)
  double cycles = 0;       // termination time / dt
  long element = 0;        // 1-based id of the controlling element
  int material = -1;       // index into Model::materials
  std::string part;        // its part
  double length = 0;       // m, its characteristic length
  double wave_speed = 0;   // m/s, the wave speed of its step (solver/directional_step)
};

/// Initial element stable step and cycle count of `model`.
CycleEstimate estimate_cycles(const model::Model& model);

/// Throws InputError when the estimate exceeds the cycle limit and control.max_cycles does not stop
/// the run before it: at control.tssfac when TSSFAC is tiny, at the controlling material's RO when
/// its wave speed is beyond any solid's, else at control.termination_time.
void require_cycle_budget(const config::Scene& scene, const model::Model& model, const CycleEstimate& estimate);

}  // namespace plyimpact::run
