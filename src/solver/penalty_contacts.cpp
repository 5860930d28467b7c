#include "solver/penalty_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "interface/interface_tiebreaks.hpp"

namespace plyimpact::solver {

model::Subsystem PenaltyContacts::describe(const model::Model& model) {
  if (model.contacts.empty())
    return {"contact", false,
            model.impactor ? "left out: an impactor is meshed, but the scene defines no contact, so the "
                             "impactor does not act on the plate"
                           : "left out: the scene defines no contact, so no contact surface or search is built"};
  std::ostringstream c;
  for (const auto& ct : model.contacts) {
    const bool single = ct.spec.type == config::ContactSpec::Type::SingleSurface;
    c << (c.tellp() > 0 ? "; " : "") << ct.spec.name << ": " << (ct.spec.eroding ? "eroding " : "automatic ")
      << (single ? "single surface " + ct.a.label : "surface to surface " + ct.a.label + " / " + ct.b.label)
      << ", SOFT " << ct.spec.SOFT;
    if (ct.spec.FS > 0 || ct.spec.FD > 0) c << ", friction FS " << ct.spec.FS << " FD " << ct.spec.FD;
  }
  bool tiebreaks = false;
  for (const auto& itf : model.interfaces) tiebreaks = tiebreaks || itf.tiebreak.has_value();
  if (tiebreaks)
    c << "; node-segment pairs a tiebreak holds are left out (a bonded pair: the faces across its interface; "
         "a separated pair: its partner's faces, where the pair's own contact acts)";
  return {"contact", true, "penalty, node to segment, bucket search; " + c.str()};
}

PenaltyContacts::PenaltyContacts(const model::Model& model, std::vector<double>& x, double dt_initial,
                                 double dt_element, const std::vector<std::unique_ptr<ForceContributor>>* contributors)
    : contributors_(contributors) {
  if (auto rule = std::make_unique<contact::BondedInterfaces>(model); !rule->empty()) bonded_ = std::move(rule);
  contacts_.reserve(model.contacts.size());
  for (const auto& c : model.contacts) {
    contacts_.emplace_back(model, c, x, dt_initial);
    contacts_.back().exclude_bonded(bonded_.get());
    initial_penetrations_.push_back(contacts_.back().resolve_initial_penetrations(x));
  }
  // A priori check of the stiffest spring that can form (the run itself combines the element step
  // with the springs actually active): warn when it would dominate the step.
  double dt_apriori = std::numeric_limits<double>::infinity();
  std::string stiffest;
  for (const auto& c : contacts_)
    if (c.stable_step() < dt_apriori) {
      dt_apriori = c.stable_step();
      stiffest = c.name();
    }
  if (std::isfinite(dt_apriori) && dt_apriori < dt_element) {
    // Stiffer than the elements: the springs' step applies from the start, not only once they act,
    // so the first contact step cannot drive a node a whole element step deep into a stiff spring
    // (0.5 k g^2 created from nothing, more than the impact energy at 100x the default penalty).
    const double tssfac = model.control.tssfac;
    dt_floor_ = dt_apriori;
    const double dt_combined = tssfac * combined_step(dt_element, dt_apriori);
    warnings_.push_back(msg() << "contact '" << stiffest << "': the contact frequency exceeds the element step by "
                              << dt_element / dt_apriori << " x (stiffest penalty spring 2/omega = " << dt_apriori
                              << " s, elements " << dt_element << " s); while it is in contact the combined stable "
                              << "step reduces the time step from " << tssfac * dt_element << " s to about "
                              << dt_combined << " s (TSSFAC applied). Lower SLSFAC/SFS/SFM or use SOFT 1 to keep "
                              << "the element step");
  }
}

void PenaltyContacts::bind_interfaces() {
  bound_ = true;
  if (!bonded_ || contributors_ == nullptr) return;
  for (const auto& c : *contributors_)
    if (const auto* itf = dynamic_cast<const interface::InterfaceTiebreaks*>(c.get()))
      for (std::size_t k = 0; k < itf->pairs().size(); ++k) bonded_->bind(itf->interface_ids()[k], &itf->pairs()[k].damage(),
                                                                    &itf->pairs()[k].released_flags());
}

void PenaltyContacts::apply(const ForceContext& ctx) {
  if (!bound_) bind_interfaces();
  double ec = 0, ef = 0;
  for (auto& c : contacts_) {
    c.apply(ctx.x, ctx.v, ctx.f, ctx.dt, ctx.time);
    ec += c.energy();
    ef += c.friction_energy();
  }
  energy_ = ec;
  friction_ = ef;
  columns_.clear();
  for (const auto& c : contacts_) {
    const auto& f = c.forces();
    columns_.insert(columns_.end(), {f.resultant[0], f.resultant[1], f.resultant[2], f.normal, f.tangential});
  }
  row_.record(columns_, ctx.dt == 0);
}

void PenaltyContacts::energies(std::span<double> out) const {
  out[0] = energy_;
  out[1] = friction_;
}

double PenaltyContacts::stable_step() const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& c : contacts_) dt = std::min(dt, c.spring_stable_step());
  if (dt_floor_ > 0) dt = std::min(dt, dt_floor_);
  return dt;
}

void PenaltyContacts::on_erosion(const AliveMask& alive, const std::vector<double>& x) {
  for (auto& c : contacts_)
    if (c.eroding()) c.rebuild(alive, x);
}

void PenaltyContacts::mark_held_nodes(std::vector<char>& held) const {
  for (const auto& c : contacts_)
    for (Index node : c.force_nodes()) held[std::size_t(node)] = 1;
}

void PenaltyContacts::node_forces(std::vector<NodeForces>& out) const {
  for (const auto& c : contacts_) out.push_back({&c.force_nodes(), &c.node_forces(), &c.loaded_force_nodes()});
}

std::vector<std::string> PenaltyContacts::history_columns() const {
  std::vector<std::string> cols;
  for (const auto& c : contacts_)
    for (const char* q : {"_fx", "_fy", "_fz", "_normal", "_tangential"}) cols.push_back("contact_" + c.name() + q);
  return cols;
}

void PenaltyContacts::history_values(std::vector<double>& row) const {
  row.insert(row.end(), row_.row().begin(), row_.row().end());
}

void PenaltyContacts::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "contact");
  visitor.scalar("energy", energy_);
  visitor.scalar("friction", friction_);
  row_.visit_state(visitor);
  // The springs, their history and the surfaces live in each PenaltyContact.
  for (auto& c : contacts_) {
    StateGroup one(visitor, c.name());
    c.visit_state(visitor);
  }
}

}  // namespace plyimpact::solver
