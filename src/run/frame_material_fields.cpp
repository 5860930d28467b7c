#include "run/frame_material_fields.hpp"

#include <algorithm>
#include <limits>

#include "material/composite_damage.hpp"
#include "material/composite_damage_output.hpp"
#include "material/johnson_cook.hpp"
#include "material/plasticity.hpp"

namespace plyimpact::run {

using namespace solver;  // the frame reads the solver's state types throughout

void add_material_fields(const Solver& solver, output::Frame& frame) {
  const model::Model& model = solver.model();
  const State& state = solver.state();
  bool any_plastic = false, any_damage = false, any_thermal = false;
  for (const auto& blk : model.blocks) {
    const auto& mat = model.materials[blk.material];
    any_plastic = any_plastic || mat.kind == model::MaterialKind::Plastic || mat.kind == model::MaterialKind::JohnsonCook;
    any_thermal = any_thermal || (mat.kind == model::MaterialKind::JohnsonCook && mat.johnson_cook.thermal());
    any_damage = any_damage || model.materials[blk.material].kind == model::MaterialKind::CompositeDamage;
  }
  output::IntField alive{"alive", {}};
  output::Field plastic{"plastic_strain", 1, {}, {}};
  output::Field temperature{"temperature", 1, {}, {}};  // K, *MAT_015 with CP (NaN elsewhere)
  const auto& names = material::composite_damage_output_names();
  std::vector<output::Field> damage;
  if (any_damage)
    for (const char* name : names) damage.push_back({name, 1, {}, {}});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    const auto& blk = model.blocks[b];
    const auto kind = model.materials[blk.material].kind;
    const auto& st = state.blocks[b];
    for (std::size_t e = 0; e < blk.size(); ++e) {
      alive.values.push_back(solver.element_alive(int(b), Index(e)) ? 1 : 0);
      // ELFORM 2 has eight points: the plastic strain is their mean (as LS-DYNA reports a solid's);
      // the damage fields are those of the most critical point (flags, XT, XC: the smallest; the
      // criteria, transverse-shear damage, crashfront and erosion cause: the largest).
      const std::size_t points = std::size_t(blk.points());
      if (any_plastic) {
        double ep = 0;
        if (kind == model::MaterialKind::Plastic)
          for (std::size_t g = 0; g < points; ++g) ep += st.history[(e * points + g) * material::kPlasticityHistory];
        if (kind == model::MaterialKind::JohnsonCook)
          for (std::size_t g = 0; g < points; ++g) ep += st.history[(e * points + g) * material::kJohnsonCookHistory];
        plastic.values.push_back(ep / double(points));
      }
      if (any_thermal) {  // mean over the points, like the plastic strain
        const auto& mat = model.materials[blk.material];
        double T = nan;
        if (kind == model::MaterialKind::JohnsonCook && mat.johnson_cook.thermal()) {
          T = 0;
          for (std::size_t g = 0; g < points; ++g)
            T += st.history[(e * points + g) * material::kJohnsonCookHistory + material::jc_history::kTemperatureRise];
          T = mat.johnson_cook.TR + T / double(points);
        }
        temperature.values.push_back(T);
      }
      if (any_damage) {
        double values[material::kCompositeDamageOutputs];
        if (kind == model::MaterialKind::CompositeDamage) {
          material::composite_damage_output_values(&st.history[e * points * material::kCompositeDamageHistory], values);
          for (std::size_t g = 1; g < points; ++g) {
            double other[material::kCompositeDamageOutputs];
            material::composite_damage_output_values(
                &st.history[(e * points + g) * material::kCompositeDamageHistory], other);
            for (int i = 0; i < material::kCompositeDamageOutputs; ++i) {
              const bool smallest = i < 4 || i == 8 || i == 9;  // e_f e_c e_m e_d, XT, XC
              values[i] = smallest ? std::min(values[i], other[i]) : std::max(values[i], other[i]);
            }
          }
        } else {
          std::fill(values, values + material::kCompositeDamageOutputs, nan);
        }
        for (int i = 0; i < material::kCompositeDamageOutputs; ++i) damage[i].values.push_back(values[i]);
      }
    }
  }
  frame.cell_int_fields.push_back(std::move(alive));
  if (any_plastic) frame.cell_fields.push_back(std::move(plastic));
  if (any_thermal) frame.cell_fields.push_back(std::move(temperature));
  for (auto& f : damage) frame.cell_fields.push_back(std::move(f));
}

}  // namespace plyimpact::run
