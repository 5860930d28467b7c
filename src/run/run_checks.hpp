// Checks that watch a run and leave a warning in the report (and so in summary.json):
//   HourglassCheck          hourglass energy against the internal energy at every history sample, on
//                           a denominator that cannot be ~0 (run/hourglass_watch): the maximum share
//                           and pass/fail in summary.json, a warning when it fails.
//   ContactEnergyCheck      energy a contact created: the work its forces did on the bodies beyond
//                           what they did against it (run/contact_energy_watch), every cycle.
//   ContactPenetrationCheck nodes a contact released while still behind the face they were in
//                           contact with (penetrations): a line when they happen (throttled) and a
//                           warning with the first and the deepest.
//   EnergyBalanceCheck      energy ratio within 1 +- 1 % and no contributor energy (contact,
//                           interfaces) negative, at every history sample (run/energy_balance_watch).
#pragma once

#include <ostream>
#include <vector>

#include "run/contact_energy_watch.hpp"
#include "run/energy_balance_watch.hpp"
#include "run/hourglass_watch.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

class HourglassCheck : public RunObserver {
 public:
  HourglassCheck(const model::Model& model, double sample_interval, double warn_ratio);
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;
  void visit_state(StateVisitor& visitor) override;

 private:
  Sampler samples_;
  HourglassWatch watch_;
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

class ContactPenetrationCheck : public RunObserver {
 public:
  // out: where a line is printed when penetrations happen (null: none); the first of a contact and
  // then each time its count doubles, so a plate going through does not flood the output.
  explicit ContactPenetrationCheck(std::ostream* out = nullptr) : out_(out) {}
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;

 private:
  std::ostream* out_;
  std::vector<long> reported_;  // per contact, the count last printed
};

class EnergyBalanceCheck : public RunObserver {
 public:
  explicit EnergyBalanceCheck(double sample_interval) : samples_(sample_interval) {}
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;
  void visit_state(StateVisitor& visitor) override;

 private:
  void observe(const solver::Solver& solver);
  Sampler samples_;
  EnergyBalanceWatch watch_;
};

}  // namespace plyimpact::run
