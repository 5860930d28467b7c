// Cycle count before the run; see cycle_budget.hpp.
#include "run/cycle_budget.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "element/hex8.hpp"
#include "solver/directional_step.hpp"

namespace plyimpact::run {
namespace {

// Faster than sound in any solid (diamond: about 18 km/s): the density or modulus is off.
constexpr double kFastestSolidWaveSpeed = 2e4;
// Below this TSSFAC the factor itself is the reason for the count.
constexpr double kSmallTssfac = 0.05;

}  // namespace

CycleEstimate estimate_cycles(const model::Model& model) {
  CycleEstimate e;
  e.dt = std::numeric_limits<double>::infinity();
  for (const auto& b : model.blocks) {
    if (b.rigid) continue;
    const double c_material = model.materials[b.material].wave_speed;
    const std::vector<double> c_step = solver::step_wave_speeds(model, b);
    for (std::size_t k = 0; k < b.size(); ++k) {
      const double c = c_step.empty() ? c_material : c_step[k];
      element::NodeVec x;
      model::gather_reference(model.X, &b.conn[8 * k], x);
      const double length = element::hex8_volume(x) / element::hex8_max_face_area(x);
      const double dt = model.control.tssfac * length / c * (b.step_scale.empty() ? 1.0 : b.step_scale[k]);
      if (dt < e.dt) {
        e.dt = dt;
        e.element = long(b.element_id[k]);
        e.material = b.material;
        e.part = model.parts[b.part].name;
        e.length = length;
        e.wave_speed = c;
      }
    }
  }
  e.cycles = std::isfinite(e.dt) ? std::ceil(model.control.termination_time / e.dt) : 0.0;
  return e;
}

void require_cycle_budget(const config::Scene& scene, const model::Model& model, const CycleEstimate& e) {
  const auto& control = scene.control;
  const double limit = control.cycle_limit > 0 ? double(control.cycle_limit) : kDefaultCycleLimit;
  if (!(e.cycles > limit)) return;  // also a nan count from a broken material goes on to the model's checks
  if (control.max_cycles > 0 && double(control.max_cycles) <= limit) return;  // stops there (ENDCYC)
  const model::Material& mat = model.materials[std::size_t(e.material)];
  std::string key = "control.termination_time";
  if (control.tssfac < kSmallTssfac) key = "control.tssfac";
  else if (mat.wave_speed > kFastestSolidWaveSpeed) key = "materials." + mat.name + ".RO";
  throw InputError(config::at(scene.where_of(key))
                   << "the run would need about " << e.cycles << " cycles (termination time "
                   << control.termination_time << " s / stable step " << e.dt << " s of element " << e.element
                   << " in part '" << e.part << "': length " << e.length << " m, wave speed " << e.wave_speed
                   << " m/s of material '" << mat.name << "', TSSFAC " << control.tssfac
                   << "); found more cycles than the limit; allowed at most " << limit << " cycles (control.cycle_limit"
                   << (control.cycle_limit > 0 ? "" : ", default") << "): a shorter termination time, a larger "
                   << "TSSFAC, a coarser mesh or a physical density and modulus; or raise control.cycle_limit, "
                   << "or stop early with control.max_cycles");
}

}  // namespace plyimpact::run
