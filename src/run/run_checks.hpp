// Checks that watch a run and leave a warning in the report (and so in summary.json):
//   HourglassCheck      hourglass energy against the PEAK internal energy, as in LS-DYNA practice
//                       (a running ratio is meaningless early on, when the internal energy is tiny);
//                       sampled with the history rows.
//   ContactEnergyCheck  a contact's energy below zero (run/contact_energy_watch), every cycle.
//   EnergyRatioCheck    final energy ratio off 1 by more than 5 %.
#pragma once

#include <vector>

#include "run/contact_energy_watch.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

class HourglassCheck : public RunObserver {
 public:
  HourglassCheck(double sample_interval, double warn_ratio) : samples_(sample_interval), warn_ratio_(warn_ratio) {}
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;
  void visit_state(StateVisitor& visitor) override;

 private:
  Sampler samples_;
  double warn_ratio_;
  double max_ratio_ = 0, peak_internal_ = 0;
};

class ContactEnergyCheck : public RunObserver {
 public:
  explicit ContactEnergyCheck(const model::Model& model);
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;
  void visit_state(StateVisitor& visitor) override { watch_.visit_state(visitor); }

 private:
  ContactEnergyWatch watch_;
  std::vector<double> energies_;
};

class EnergyRatioCheck : public RunObserver {
 public:
  static constexpr double kTolerance = 0.05;
  void stop(const solver::Solver* solver, RunReport& report) override;
};

}  // namespace plyimpact::run
