// The model's delaminating interfaces as one force contributor: one cohesive::TiebreakPairs per
// interface that has a tiebreak law (model::Interface::tiebreak), built on its duplicated node pairs
// (tributary areas and normals from the mesh, faces from the lower segments so the frame follows
// the deforming interface). Forces in the Forces phase; energies: the interfaces' elastic energy
// and the energy they dissipated (damage, friction after separation), both part of the total and
// shown apart; stable step: the stiffest pair alone (the solver combines it with the element step
// as it does the contact springs). A pre-crack is part of the initial history: the pairs whose
// reference position lies in the region start with damage 1 (separated: contact only).
// History: the delaminated (damage 1) area in total and per interface, pre-crack included.
#pragma once

#include <string>
#include <vector>

#include "cohesive/tiebreak_pairs.hpp"
#include "solver/force_contributor.hpp"

namespace plyimpact::interface {

class InterfaceTiebreaks : public solver::ForceContributor {
 public:
  // Active when some interface has a tiebreak law; the detail gives each law and its pair step.
  static model::Subsystem describe(const model::Model& model);
  // dt_element: the elements' stable step (no TSSFAC), for the warning when the pairs set the step.
  InterfaceTiebreaks(const model::Model& model, double dt_element);

  std::string name() const override { return "interfaces"; }
  void apply(const solver::ForceContext& context) override;
  std::vector<solver::EnergyName> energy_names() const override {
    return {{"interface_elastic", "interface_elastic_energy", true},
            {"interface_dissipated", "interface_dissipated_energy", true}};
  }
  void energies(std::span<double> out) const override;
  double stable_step() const override { return stable_step_; }
  std::vector<std::string> warnings() const override { return warnings_; }
  std::vector<std::string> history_columns() const override;
  void history_values(std::vector<double>& row) const override;
  void visit_state(StateVisitor& visitor) override;

  const std::vector<cohesive::TiebreakPairs>& pairs() const { return pairs_; }
  const std::vector<int>& interface_ids() const { return ids_; }  // 1-based number of each pairs_ entry
  double delaminated_area() const;                                 // m^2, all interfaces

 private:
  std::vector<cohesive::TiebreakPairs> pairs_;
  std::vector<int> ids_;
  std::vector<std::string> warnings_;
  double stable_step_ = 0;
};

// The kernel of one interface (exposed for `check` and tests): pairs, areas, normals and faces of
// `itf`, its law, and its pre-crack applied to the initial damage.
cohesive::TiebreakPairs make_interface_pairs(const model::Model& model, const model::Interface& itf);

// One line naming the law and its card values ("OPTION 9 (bilinear mixed mode), NFLS 60 MPa, ...").
std::string tiebreak_law_text(const cohesive::TractionLawParams& p);

}  // namespace plyimpact::interface
