#include "run/run_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace plyimpact::run {

void HourglassCheck::after_cycle(const solver::Solver& solver) {
  const double t = solver.state().time;
  if (!samples_.due(t) || !(solver.balance().time > 0)) return;
  samples_.advance(t);
  const solver::Energies& e = solver.balance();
  peak_internal_ = std::max(peak_internal_, e.internal());
  if (peak_internal_ > 0) max_ratio_ = std::max(max_ratio_, e.hourglass() / peak_internal_);
}

void HourglassCheck::stop(const solver::Solver* solver, RunReport& report) {
  (void)solver;
  if (!(max_ratio_ > warn_ratio_)) return;
  char w[200];
  std::snprintf(w, sizeof w, "hourglass energy reached %.1f%% of the peak internal energy (limit %.1f%%): refine the mesh "
                "(more elements through the thickness) or use ELFORM 2", 100 * max_ratio_, 100 * warn_ratio_);
  report.warnings.push_back(w);
}

void HourglassCheck::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "hourglass_check");
  samples_.visit_state(visitor, "next_sample_time");
  visitor.scalar("max_ratio", max_ratio_);
  visitor.scalar("peak_internal", peak_internal_);
}

namespace {
std::vector<std::string> contact_names(const model::Model& model) {
  std::vector<std::string> names;
  for (const auto& c : model.contacts) names.push_back(c.spec.name);
  return names;
}
}  // namespace

ContactEnergyCheck::ContactEnergyCheck(const model::Model& model)
    : watch_(contact_names(model)), energies_(model.contacts.size(), 0.0) {}

void ContactEnergyCheck::after_cycle(const solver::Solver& solver) {
  if (energies_.empty()) return;
  for (std::size_t c = 0; c < energies_.size(); ++c) energies_[c] = solver.contacts()[c].energy();
  watch_.observe(energies_, solver.state().time, solver.state().initial_total_energy + solver.balance().external_work());
}

void ContactEnergyCheck::stop(const solver::Solver* solver, RunReport& report) {
  (void)solver;
  for (const auto& w : watch_.warnings()) report.warnings.push_back(w);
}

void EnergyRatioCheck::stop(const solver::Solver* solver, RunReport& report) {
  if (solver && std::abs(report.energy_ratio - 1.0) > kTolerance)
    report.warnings.push_back("energy ratio " + std::to_string(report.energy_ratio) + " differs from 1 by more than 5%");
}

}  // namespace plyimpact::run
