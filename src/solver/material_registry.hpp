// The one place that ties a material kind to its update class in material/ (the entry point of the
// element pass) and builds that class from the model and the run state. A new material: its
// params, point update and lane class in its own file under material/, one MaterialKind, and one
// case in with_material below (plus its card in config/ and its spec conversion in
// model/material_builder.cpp).
//
// A material class provides (see material/isotropic_elastic_lanes.hpp, the simplest):
//   kTotalLagrangian, kElementRotation, kIncremental   which kinematics it reads;
//   update(LanePoint, s_old, s, erode)                   kLanes one-point elements (ELFORM 1);
//   update_point(Point, s, history) -> erosion code      one point of a multi-point element;
//   commit(e, lane)                                      per-element state of a surviving lane;
//   begin_element / end_element                          only with kElementRotation.
#pragma once

#include "material/composite_damage_lanes.hpp"
#include "material/isotropic_elastic_lanes.hpp"
#include "material/johnson_cook_lanes.hpp"
#include "material/orthotropic_elastic_lanes.hpp"
#include "material/plasticity_lanes.hpp"
#include "model/model.hpp"
#include "solver/erosion.hpp"
#include "solver/state.hpp"

namespace plyimpact::solver {

// The view of the block's erosion neighbourhoods for this pass (empty without any).
inline material::ErosionNeighbourhoodView erosion_neighbourhood(const model::ElementBlock& blk, BlockState& st) {
  material::ErosionNeighbourhoodView v;
  const auto& n = blk.erosion_neighbours;
  if (n.empty()) return v;
  v.start = n.start.data(), v.index = n.index.data(), v.weight = n.weight.data(), v.self_weight = n.self_weight.data();
  v.read = st.erosion_strain[st.erosion_strain_read].data();
  v.write = st.erosion_strain[1 - st.erosion_strain_read].data();
  return v;
}

// Calls f(material) with the update class of the block's material, built for this block and state.
// Every template instance of f (one per material) is compiled once; the choice is made per chunk.
template <class F>
void with_material(const model::Model& model, const model::ElementBlock& blk, BlockState& st, F&& f) {
  const model::Material& mat = model.materials[blk.material];
  switch (mat.kind) {
    case model::MaterialKind::OrthotropicElastic:
      return f(material::OrthotropicElasticLanes(blk.reference_jacobian_inverse.data(), blk.orientation.data(),
                                                 model.orientations.data()));
    case model::MaterialKind::Plastic:
      return f(material::PlasticityLanes(mat.plastic, st.history.data(), int(ErosionCause::PlasticStrain)));
    case model::MaterialKind::CompositeDamage:
      return f(material::CompositeDamageLanes(mat.composite, st.history.data(), st.axes.data(), st.initial_dt.data(),
                                              blk.erosion_scale.empty() ? nullptr : blk.erosion_scale.data(),
                                              erosion_neighbourhood(blk, st), blk.points(),
                                              int(ErosionCause::CompositeBase)));
    case model::MaterialKind::JohnsonCook:
      return f(material::JohnsonCookLanes(mat.johnson_cook, st.history.data(), int(ErosionCause::PlasticStrain)));
    default:
      return f(material::IsotropicElasticLanes(mat.iso));
  }
}

}  // namespace plyimpact::solver
