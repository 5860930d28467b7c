#include "solver/frame_material_fields.hpp"

#include <limits>

#include "material/composite_damage.hpp"
#include "material/composite_damage_output.hpp"
#include "material/plasticity.hpp"

namespace plyimpact::solver {

void add_material_fields(const Solver& solver, output::Frame& frame) {
  const model::Model& model = solver.model();
  const State& state = solver.state();
  bool any_plastic = false, any_damage = false;
  for (const auto& blk : model.blocks) {
    any_plastic = any_plastic || model.materials[blk.material].kind == model::MaterialKind::Plastic;
    any_damage = any_damage || model.materials[blk.material].kind == model::MaterialKind::CompositeDamage;
  }
  output::IntField alive{"alive", {}};
  output::Field plastic{"plastic_strain", 1, {}, {}};
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
      if (any_plastic)
        plastic.values.push_back(kind == model::MaterialKind::Plastic
                                     ? st.history[e * material::kPlasticityHistory]  // one point (ELFORM 1)
                                     : 0.0);
      if (any_damage) {
        double values[material::kCompositeDamageOutputs];
        if (kind == model::MaterialKind::CompositeDamage)
          material::composite_damage_output_values(&st.history[e * material::kCompositeDamageHistory], values);
        else
          std::fill(values, values + material::kCompositeDamageOutputs, nan);
        for (int i = 0; i < material::kCompositeDamageOutputs; ++i) damage[i].values.push_back(values[i]);
      }
    }
  }
  frame.cell_int_fields.push_back(std::move(alive));
  if (any_plastic) frame.cell_fields.push_back(std::move(plastic));
  for (auto& f : damage) frame.cell_fields.push_back(std::move(f));
}

}  // namespace plyimpact::solver
