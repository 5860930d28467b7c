#include "run/run_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace plyimpact::run {

namespace {

// The energy ratio's reference: initial total energy + external work.
double reference_energy(const solver::Solver& solver) {
  return solver.state().initial_total_energy + solver.balance().external_work();
}

std::vector<std::string> contact_names(const model::Model& model) {
  std::vector<std::string> names;
  for (const auto& c : model.contacts) names.push_back(c.spec.name);
  return names;
}

// "node 1234 at t = 1.2e-05 s, 0.31 mm deep": the node as its 1-based number (the .msh tag).
std::string describe(const contact::PenetrationEvent& e) {
  char b[160];
  std::snprintf(b, sizeof b, "node %ld at t = %.4g s, %.4g mm deep", long(e.node) + 1, e.time, 1e3 * e.depth);
  return b;
}

// Each part's hourglass energy, J: the sum over its elements, live and eroded (an eroded element
// keeps what it held, as the run's total does).
std::vector<double> hourglass_by_part(const solver::Solver& solver) {
  const model::Model& model = solver.model();
  std::vector<double> joules(model.parts.size(), 0.0);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const int b = model.parts[p].block;
    if (b < 0 || std::size_t(b) >= solver.state().blocks.size()) continue;
    for (double h : solver.state().blocks[std::size_t(b)].hourglass_energy) joules[p] += h;
  }
  return joules;
}

}  // namespace

HourglassCheck::HourglassCheck(const model::Model& model, double sample_interval, double warn_ratio)
    : samples_(sample_interval), watch_(warn_ratio) {
  std::vector<std::string> names;
  for (const auto& part : model.parts) names.push_back(part.name);
  watch_.name_parts(std::move(names));
}

void HourglassCheck::after_cycle(const solver::Solver& solver) {
  const double t = solver.state().time;
  if (!samples_.due(t) || !(solver.balance().time > 0)) return;
  samples_.advance(t);
  const solver::Energies& e = solver.balance();
  if (watch_.observe(e.time, e.hourglass(), e.internal(), reference_energy(solver),
                     solver.state().eroded_hourglass_energy))
    watch_.record_by_part(hourglass_by_part(solver));
}

void HourglassCheck::stop(const solver::Solver* solver, RunReport& report) {
  (void)solver;
  report.hourglass = watch_.verdict();
  if (watch_.exceeded()) report.warnings.push_back(watch_.warning());
}

void HourglassCheck::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "hourglass_check");
  samples_.visit_state(visitor, "next_sample_time");
  watch_.visit_state(visitor);
}

ContactEnergyCheck::ContactEnergyCheck(const model::Model& model)
    : watch_(contact_names(model)), energies_(model.contacts.size(), 0.0) {}

void ContactEnergyCheck::after_cycle(const solver::Solver& solver) {
  if (energies_.empty()) return;
  // What the contact took from the bodies minus what it holds and dissipated: below zero it gave
  // them energy nobody put in.
  for (std::size_t c = 0; c < energies_.size(); ++c) energies_[c] = -solver.contacts()[c].created();
  watch_.observe(energies_, solver.state().time, reference_energy(solver));
}

void ContactEnergyCheck::stop(const solver::Solver* solver, RunReport& report) {
  (void)solver;
  for (const auto& w : watch_.warnings()) report.warnings.push_back(w);
}

void ContactPenetrationCheck::after_cycle(const solver::Solver& solver) {
  const auto& contacts = solver.contacts();
  reported_.resize(contacts.size(), 0);
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const contact::Penetrations& p = contacts[c].penetrations();
    if (p.count == 0 || p.count < 2 * reported_[c] || p.count == reported_[c]) continue;
    if (out_)
      *out_ << "warning: contact '" << contacts[c].name() << "': " << p.count << " node(s) passed through the surface "
            << "and were released, the latest " << describe(p.last) << "\n";
    reported_[c] = p.count;
  }
}

void ContactPenetrationCheck::stop(const solver::Solver* solver, RunReport& report) {
  if (!solver) return;
  for (const auto& c : solver->contacts()) {
    const contact::Penetrations& p = c.penetrations();
    if (p.count == 0) continue;
    report.warnings.push_back("contact '" + c.name() + "': " + std::to_string(p.count) +
                              " penetration(s): nodes passed through the surface and were released (the contact "
                              "no longer holds them, and the " + std::to_string(p.released_potential) +
                              " J their springs held left the energy balance), first " + describe(p.first) + ", deepest " +
                              describe(p.deepest) + "; the bodies interpenetrate: raise the penalty (SLSFAC, SOFT 1) "
                              "or refine the contact surfaces");
  }
}

void EnergyBalanceCheck::observe(const solver::Solver& solver) {
  watch_.observe(solver.balance(), solver.energy_ratio(), reference_energy(solver), solver.state().cycle);
}

void EnergyBalanceCheck::after_cycle(const solver::Solver& solver) {
  const double t = solver.state().time;
  if (!samples_.due(t) || !(solver.balance().time > 0)) return;
  samples_.advance(t);
  observe(solver);
}

void EnergyBalanceCheck::stop(const solver::Solver* solver, RunReport& report) {
  if (!solver) return;
  observe(*solver);  // the final state, whatever the sampling
  report.energy_balance = watch_.verdict();
  for (std::string& w : watch_.warnings()) report.warnings.push_back(std::move(w));
}

void EnergyBalanceCheck::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "energy_balance_check");
  samples_.visit_state(visitor, "next_sample_time");
  watch_.visit_state(visitor);
}

}  // namespace plyimpact::run
