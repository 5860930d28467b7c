// The scene's tiebreak contacts (contacts of type tiebreak_surface_to_surface, LS-DYNA's
// *CONTACT_..._SURFACE_TO_SURFACE_TIEBREAK) as one force contributor: per contact, the slave nodes of
// side a tied to points of side b's segments (segment_tying.hpp) and held by the card's law
// (cohesive::SegmentTiebreaks). Unlike the laminate's interfaces, the two meshes need not match.
// Energies: elastic and dissipated, in the total and shown apart; stable step: the stiffest tie;
// erosion: a tie whose master element is deleted lets go; history: the separated (delaminated) area
// of each contact; `check` and the run report how many slave nodes were tied and why the others
// were not. Outputs: an InterfaceSampleSource (interface_output.hpp) per contact, its sample points the
// ties.
#pragma once

#include <string>
#include <vector>

#include "cohesive/segment_tiebreaks.hpp"
#include "interface/interface_output.hpp"
#include "interface/segment_tying.hpp"
#include "solver/force_contributor.hpp"

namespace plyimpact::interface {

// The tying of one tiebreak contact on the reference mesh, with each tie's master element.
struct ContactTying {
  TyingResult result;
  std::vector<int> master_block;       // (num_ties) block of the master segment's element
  std::vector<Index> master_element;   // (num_ties) element index within that block
  std::vector<Index> slave_faces;      // (num, 4) the slave side's exterior faces (node indices)
};
ContactTying tie_contact(const model::Model& model, const model::Contact& contact);

class SurfaceTiebreaks : public solver::ForceContributor, public InterfaceSampleSource {
 public:
  static model::Subsystem describe(const model::Model& model);
  SurfaceTiebreaks(const model::Model& model, double dt_element);

  std::string name() const override { return "tiebreak_contacts"; }
  void apply(const solver::ForceContext& context) override;
  std::vector<solver::EnergyName> energy_names() const override {
    return {{"tiebreak_elastic", "tiebreak_elastic_energy", true},
            {"tiebreak_dissipated", "tiebreak_dissipated_energy", true}};
  }
  void energies(std::span<double> out) const override;
  double stable_step() const override { return stable_step_; }
  std::vector<std::string> warnings() const override { return warnings_; }
  void on_erosion(const solver::AliveMask& alive, const std::vector<double>& x) override;
  // The slave node and the master segment's nodes of every tie not released.
  void mark_held_nodes(std::vector<char>& held) const override;
  std::vector<std::string> history_columns() const override;
  void history_values(std::vector<double>& row) const override;
  void visit_state(StateVisitor& visitor) override;

  const std::vector<cohesive::SegmentTiebreaks>& contacts() const { return ties_; }

  std::size_t num_interfaces() const override { return layouts_.size(); }
  const InterfaceLayout& layout(std::size_t i) const override { return layouts_[i]; }
  void sample(std::size_t i, const double* x, cohesive::PairSample* out) const override { ties_[i].sample(x, out); }
  const std::vector<double>& damage(std::size_t i) const override { return ties_[i].damage(); }
  double delaminated_area(std::size_t i) const override { return ties_[i].separated_area(); }

 private:
  std::vector<std::string> names_;
  std::vector<cohesive::SegmentTiebreaks> ties_;
  std::vector<ContactTying> tying_;
  std::vector<InterfaceLayout> layouts_;  // (ties_.size()) for the outputs
  std::vector<std::string> warnings_;
  double stable_step_ = 0;
};

}  // namespace plyimpact::interface
