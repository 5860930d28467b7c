// The model's delaminating interfaces as one force contributor: one cohesive::TiebreakPairs per
// interface that has a tiebreak law (model::Interface::tiebreak), built on its duplicated node pairs
// (tributary areas and normals from the mesh, faces from the lower segments so the frame follows
// the deforming interface). Forces in the Forces phase; energies: the interfaces' elastic energy
// and the energy they dissipated (damage, friction after separation), both part of the total and
// shown apart; stable step: the stiffest pair alone (the solver combines it with the element step
// as it does the contact springs). A pre-crack is part of the initial history: the pairs whose
// reference position lies in the region start with damage 1 (separated: contact only).
// History: the delaminated (damage 1) area in total and per interface, pre-crack included.
// An interface with `model: cohesive` gets *MAT_138 cohesive elements (cohesive::CohesiveElements,
// one per interface segment) instead of pairs; they report under the same energies and columns.
// Outputs: an InterfaceSampleSource (interface_output.hpp) over all interfaces in id order, whose
// sample points are the pairs or the elements' integration points.
#pragma once

#include <string>
#include <vector>

#include "cohesive/cohesive_elements.hpp"
#include "cohesive/tiebreak_pairs.hpp"
#include "interface/interface_output.hpp"
#include "solver/force_contributor.hpp"

namespace plyimpact::interface {

class InterfaceTiebreaks : public solver::ForceContributor, public InterfaceSampleSource {
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
  // Releases for good every pair with no live element left around its lower or its upper node.
  void on_erosion(const solver::AliveMask& alive, const std::vector<double>& x) override;
  // Both nodes of every pair not released, and the nodes of every cohesive element (never deleted).
  void mark_held_nodes(std::vector<char>& held) const override;

  const std::vector<cohesive::TiebreakPairs>& pairs() const { return pairs_; }
  const std::vector<int>& interface_ids() const { return ids_; }  // 1-based number of each pairs_ entry
  double delaminated_area() const;                                 // m^2, all interfaces
  const std::vector<cohesive::CohesiveElements>& cohesive() const { return cohesive_; }
  const std::vector<int>& cohesive_ids() const { return cohesive_ids_; }  // 1-based number of each cohesive_ entry

  std::size_t num_interfaces() const override { return layouts_.size(); }
  const InterfaceLayout& layout(std::size_t i) const override { return layouts_[i]; }
  void sample(std::size_t i, const double* x, cohesive::PairSample* out) const override;
  const std::vector<double>& damage(std::size_t i) const override;
  double delaminated_area(std::size_t i) const override;

 private:
  std::vector<cohesive::TiebreakPairs> pairs_;
  std::vector<int> ids_;
  const model::Model* model_ = nullptr;                   // the element blocks, for on_erosion
  std::vector<const model::Interface*> pair_interfaces_;  // (pairs_.size()) the model's interface of each
  std::vector<InterfaceLayout> layouts_;  // (columns_.size()) for the outputs, in id order
  std::vector<cohesive::CohesiveElements> cohesive_;
  std::vector<int> cohesive_ids_;
  std::vector<std::pair<bool, std::size_t>> columns_;  // per interface in id order: (cohesive, index)
  std::vector<std::string> warnings_;
  double stable_step_ = 0;
  bool across_interfaces_ = true;  // no node in two interfaces: apply runs the interfaces in parallel
};

// The kernel of one interface (exposed for `check` and tests): pairs, areas, normals and faces of
// `itf`, its law, and its pre-crack applied to the initial damage.
cohesive::TiebreakPairs make_interface_pairs(const model::Model& model, const model::Interface& itf);

// The *MAT_138 elements of one `model: cohesive` interface: one per interface segment (lower face from
// the lower segment, upper face from the partner nodes), its law and integration rule (INTFAIL), and
// its pre-crack: the points whose reference position lies in the region start separated (the
// tiebreak's rule for its pairs; with corner points the two rules coincide).
cohesive::CohesiveElements make_interface_cohesive(const model::Model& model, const model::Interface& itf);

// One line naming the law and its card values ("OPTION 9 (bilinear mixed mode), NFLS 60 MPa, ...").
std::string tiebreak_law_text(const cohesive::TractionLawParams& p);

}  // namespace plyimpact::interface
