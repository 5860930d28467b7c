#include "run/frame_material_fields.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "material/composite_damage.hpp"
#include "material/composite_damage_output.hpp"
#include "material/johnson_cook.hpp"
#include "material/plasticity.hpp"
#include "run/frame_legends.hpp"

namespace plyimpact::run {

using namespace solver;  // the frame reads the solver's state types throughout

namespace {

// Units of the *MAT_054 outputs, in the order of material::composite_damage_output_names(): four
// mode flags, four criterion values, XT and XC, transverse shear damage, crashfront, erosion cause.
constexpr std::array<const char*, material::kCompositeDamageOutputs> kDamageUnits = {
    "code", "code", "code", "code", "1", "1", "1", "1", "Pa", "Pa", "1", "code", "code"};

// What each erosion cause means, indexed by material::CompositeDamageCause.
constexpr std::array<const char*, 9> kCauseDetail = {
    "",
    "fibre-tension criterion met (DFAILT = 0)",
    "fibre strain eps_aa >= DFAILT",
    "fibre strain eps_aa <= DFAILC",
    "matrix strain |eps_bb| >= DFAILM",
    "tensor shear strain |eps_ab| >= DFAILS",
    "effective strain >= EFS",
    "element time step below TFAIL",
    "transverse shear damage reached TSMD (EPSR < 0)"};

void add_damage_legends(output::Frame& frame) {
  const char* flag_names[4] = {"mat054_ef", "mat054_ec", "mat054_em", "mat054_ed"};
  const char* modes[4] = {"fibre tension", "fibre compression", "matrix tension", "matrix compression"};
  for (int i = 0; i < 4; ++i)
    frame.field_strings.push_back({std::string("legend_") + flag_names[i],
                                   {std::string("1: ") + modes[i] + " intact", std::string("0: ") + modes[i] +
                                                                                   " failed (permanent)"}});
  output::StringField cause{"legend_mat054_erosion_cause", {"0: alive"}};
  for (int c = 1; c < int(kCauseDetail.size()); ++c)
    cause.values.push_back(std::to_string(c) + ": " +
                           material::composite_damage_cause_name(material::CompositeDamageCause(c)) + " (" +
                           kCauseDetail[std::size_t(c)] + ")");
  frame.field_strings.push_back(std::move(cause));
  frame.field_strings.push_back({"legend_mat054_crashfront",
                                 {"0: no eroded neighbour", "1: shares a node with an eroded element (strengths x SOFT "
                                                            "when TFAIL > 0)"}});
}

}  // namespace

void add_material_fields(const Solver& solver, output::Frame& frame) {
  const model::Model& model = solver.model();
  const State& state = solver.state();
  bool any_plastic = false, any_damage = false, any_thermal = false;
  for (const auto& blk : model.blocks) {
    if (!in_bodies_frame(blk)) continue;
    const auto& mat = model.materials[blk.material];
    any_plastic = any_plastic || mat.kind == model::MaterialKind::Plastic || mat.kind == model::MaterialKind::JohnsonCook;
    any_thermal = any_thermal || (mat.kind == model::MaterialKind::JohnsonCook && mat.johnson_cook.thermal());
    any_damage = any_damage || mat.kind == model::MaterialKind::CompositeDamage;
  }
  output::IntField alive{"alive", {}, "code"};
  output::Field plastic{"plastic_strain", 1, {}, {}, "1"};
  output::Field temperature{"temperature", 1, {}, {}, "K"};  // *MAT_015 with CP (NaN elsewhere)
  const auto& names = material::composite_damage_output_names();
  std::vector<output::Field> damage;
  if (any_damage)
    for (int i = 0; i < material::kCompositeDamageOutputs; ++i) damage.push_back({names[i], 1, {}, {}, kDamageUnits[i]});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    const auto& blk = model.blocks[b];
    if (!in_bodies_frame(blk)) continue;
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
  frame.field_strings.push_back({"legend_alive", {"1: carries load", "0: eroded (no stress, no hourglass force; "
                                                                     "its mass stays on its nodes)"}});
  std::vector<std::string> notes;
  if (any_plastic) {
    frame.cell_fields.push_back(std::move(plastic));
    notes.push_back("plastic_strain: effective plastic strain of *MAT_003/024/015/098; 0 in other materials");
  }
  if (any_thermal) {
    frame.cell_fields.push_back(std::move(temperature));
    notes.push_back("temperature: *MAT_015 with CP (adiabatic heating); NaN in other materials");
  }
  if (any_damage) {
    for (auto& f : damage) frame.cell_fields.push_back(std::move(f));
    add_damage_legends(frame);
    notes.push_back("mat054_*: *MAT_054/055 state; NaN (no value) in cells of other materials, which have no "
                    "such state; mat054_crit_*: criterion minus 1, >= 0 failed, -1 when the stress sign does "
                    "not load the mode");
  }
  if (!notes.empty()) frame.field_strings.push_back({"notes", std::move(notes)});
}

}  // namespace plyimpact::run
