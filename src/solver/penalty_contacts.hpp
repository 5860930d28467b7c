// The scene's penalty contacts (contact/penalty_contact) as one force contributor: built after the
// initial element pass (their SOFT 1/2 stiffness needs the initial step), initial penetrations
// resolved at once, forces in the Forces phase. The stable-step bound is the Gershgorin step of the
// springs active in the last pass, floored by the a priori step of the stiffest possible spring
// when that is below the element step (so a first contact cannot drive a node a whole element
// step deep into a stiff spring). Energies: contact (SLNTEN = 2, friction and damping included)
// and, shown on its own, friction.
// With delaminating interfaces, every contact leaves out the node-segment pairs a tiebreak holds
// (contact/bonded_interfaces: bonded pairs, and a separated pair's own faces): the rule is built
// from the model's pairs here and reads the pairs' damage from the interfaces' contributor, which
// the solver builds after this one, so it is bound at the first apply (and counts every pair as
// bonded until then: the initial penetrations see the bonded plies at t = 0).
#pragma once

#include <memory>

#include "contact/bonded_interfaces.hpp"
#include "contact/penalty_contact.hpp"
#include "solver/force_contributor.hpp"
#include "solver/row_lag.hpp"

namespace plyimpact::solver {

class PenaltyContacts : public ForceContributor {
 public:
  static model::Subsystem describe(const model::Model& model);
  // x: positions at t = 0 (initial penetrations may move nodes onto the surface); dt_initial: the
  // initial solution step (TSSFAC applied); dt_element: the elements' stable step (no TSSFAC).
  // contributors: the solver's list, where the interfaces' damage is found (null: none bound).
  PenaltyContacts(const model::Model& model, std::vector<double>& x, double dt_initial, double dt_element,
                  const std::vector<std::unique_ptr<ForceContributor>>* contributors = nullptr);

  std::string name() const override { return "contact"; }
  void apply(const ForceContext& context) override;
  std::vector<EnergyName> energy_names() const override {
    return {{"contact", "contact_energy", true}, {"friction", "friction_energy", false}};
  }
  void energies(std::span<double> out) const override;
  double stable_step() const override;
  std::vector<std::string> warnings() const override { return warnings_; }
  void on_erosion(const AliveMask& alive, const std::vector<double>& x) override;
  // The nodes of every contact's surfaces as they are now (an eroding contact with ENMASS 1 keeps
  // its orphans there; with ENMASS 0 they have left it).
  void mark_held_nodes(std::vector<char>& held) const override;
  void node_forces(std::vector<NodeForces>& out) const override;
  std::vector<std::string> history_columns() const override;
  void history_values(std::vector<double>& row) const override;
  void visit_state(StateVisitor& visitor) override;

  const std::vector<contact::PenaltyContact>& contacts() const { return contacts_; }
  const std::vector<contact::InitialPenetrations>& initial_penetrations() const { return initial_penetrations_; }
  const contact::BondedInterfaces* bonded_interfaces() const { return bonded_.get(); }

 private:
  // Binds the interfaces' damage to bonded_ (once the solver's list is complete).
  void bind_interfaces();

  std::vector<contact::PenaltyContact> contacts_;
  std::unique_ptr<contact::BondedInterfaces> bonded_;  // null: no delaminating interface
  const std::vector<std::unique_ptr<ForceContributor>>* contributors_ = nullptr;
  bool bound_ = false;
  std::vector<contact::InitialPenetrations> initial_penetrations_;
  std::vector<std::string> warnings_;
  double dt_floor_ = 0;             // s, a priori step when stiffer than the elements, else 0
  double energy_ = 0, friction_ = 0;  // J, sums over the contacts at the last apply
  std::vector<double> columns_;     // scratch: the last pass's force columns
  RowLag row_;                      // the force columns at the history row's time
};

}  // namespace plyimpact::solver
