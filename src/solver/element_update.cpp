#include "solver/element_update.hpp"

#include <algorithm>

#include "material/composite_damage.hpp"
#include "material/erosion_neighbourhood.hpp"
#include "solver/assumed_strain_hourglass.hpp"
#include "solver/directional_step.hpp"
#include "solver/element_families.hpp"

namespace plyimpact::solver {

void update_elements(const model::Model& model, const model::ElementBlock& block, BlockState& state, Index begin,
                     Index end, const double* x, const double* v, double* f, double dt, ChunkResult& result) {
  // Accumulate in a local copy and write once: results of neighbouring chunks share cache lines and
  // are written by different threads.
  ChunkResult local;
  switch (element_family(block)) {
    case ElementFamily::Hex8OnePoint: update_hex8_one_point(model, block, state, begin, end, x, v, f, dt, local); break;
    case ElementFamily::Hex8SelectiveReduced:
      update_hex8_selective(model, block, state, begin, end, x, v, f, dt, local);
      break;
  }
  result = local;
}

BlockState initial_block_state(const model::Model& model, std::size_t b) {
  const auto& blk = model.blocks[b];
  BlockState st;
  st.stress.assign(6 * blk.size() * blk.points(), 0.0);
  if (blk.hourglass() != model::HourglassKind::None) st.hourglass.assign(12 * blk.size(), 0.0);
  st.hourglass_moduli = hourglass_moduli(model, blk);
  st.step_wave_speed = step_wave_speeds(model, blk);
  st.bulk_q.assign(blk.size(), 0.0);
  st.step_q.assign(blk.size(), 0.0);
  st.internal_energy.assign(blk.size(), 0.0);
  st.hourglass_energy.assign(blk.size(), 0.0);
  st.volume = blk.volume0;
  const model::Material& mat = model.materials[blk.material];
  const int h = mat.history_size();
  if (h > 0) st.history.assign(std::size_t(h) * blk.size() * blk.points(), 0.0);
  if (mat.kind == model::MaterialKind::CompositeDamage) {
    for (std::size_t q = 0; q < blk.size() * blk.points(); ++q)
      material::composite_damage_init(mat.composite, &st.history[q * std::size_t(h)]);
    st.axes.resize(9 * blk.size());
    for (std::size_t e = 0; e < blk.size(); ++e) {
      const auto& a = model.orientations[blk.orientation[e]].axes;
      std::copy(a.begin(), a.end(), st.axes.begin() + 9 * e);
    }
    st.initial_dt.assign(blk.size(), 0.0);
    if (!blk.erosion_neighbours.empty())  // strain-free at t = 0
      for (auto& buffer : st.erosion_strain) buffer.assign(material::kErosionStrainStride * blk.size(), 0.0);
  }
  return st;
}

std::vector<double> initial_element_steps(const model::Model& model, std::size_t b) {
  const auto& blk = model.blocks[b];
  BlockState st = initial_block_state(model, b);
  st.initial_dt.assign(blk.size(), 0.0);  // the families record each element's t = 0 step here
  const std::vector<double> v(model.X.size(), 0.0);
  std::vector<double> f(model.X.size(), 0.0);
  ChunkResult result;
  update_elements(model, blk, st, 0, Index(blk.size()), model.X.data(), v.data(), f.data(), 0.0, result);
  return st.initial_dt;
}

}  // namespace plyimpact::solver
