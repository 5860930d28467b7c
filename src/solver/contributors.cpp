#include "solver/contributors.hpp"

#include "interface/interface_tiebreaks.hpp"
#include "interface/surface_tiebreaks.hpp"
#include "solver/gravity.hpp"
#include "solver/impactor_motion.hpp"
#include "solver/penalty_contacts.hpp"
#include "solver/rigid_body_coupling.hpp"
#include "solver/rigid_walls.hpp"

namespace plyimpact::solver {

const std::vector<ContributorType>& contributor_types() {
  static const std::vector<ContributorType> types = {
      {&Gravity::describe, [](ContributorSetup& s) -> std::unique_ptr<ForceContributor> {
         return std::make_unique<Gravity>(s.model);
       }},
      {&PenaltyContacts::describe, [](ContributorSetup& s) -> std::unique_ptr<ForceContributor> {
         return std::make_unique<PenaltyContacts>(s.model, s.x, s.dt_initial, s.dt_element, &s.contributors);
       }},
      {&RigidWalls::describe, [](ContributorSetup& s) -> std::unique_ptr<ForceContributor> {
         return std::make_unique<RigidWalls>(s.model);
       }},
      {&RigidBodyCoupling::describe, [](ContributorSetup& s) -> std::unique_ptr<ForceContributor> {
         return std::make_unique<RigidBodyCoupling>(s.model, *s.bodies, s.node_body, s.contributors);
       }},
      {&ImpactorMotion::describe, [](ContributorSetup& s) -> std::unique_ptr<ForceContributor> {
         return std::make_unique<ImpactorMotion>(s.model);
       }},
      {&interface::InterfaceTiebreaks::describe, [](ContributorSetup& s) -> std::unique_ptr<ForceContributor> {
         return std::make_unique<interface::InterfaceTiebreaks>(s.model, s.dt_element);
       }},
      {&interface::SurfaceTiebreaks::describe, [](ContributorSetup& s) -> std::unique_ptr<ForceContributor> {
         return std::make_unique<interface::SurfaceTiebreaks>(s.model, s.dt_element);
       }},
  };
  return types;
}

std::vector<model::Subsystem> subsystems(const model::Model& model) {
  std::vector<model::Subsystem> list = model::subsystems(model);
  std::vector<model::Subsystem> forces;
  for (const auto& t : contributor_types()) forces.push_back(t.describe(model));
  // After the boundary conditions, before the model-level subsystems that follow them.
  auto at = list.begin();
  while (at != list.end() && at->name != "boundary_conditions") ++at;
  if (at != list.end()) ++at;
  list.insert(at, forces.begin(), forces.end());
  return list;
}

}  // namespace plyimpact::solver
