// *TERMINATION_CONTACT (control.termination_contact): ends a run as a normal termination once the
// named contact's resultant force has stayed at or below THRES for DUR, timed from ACTIM on. An
// impact scene needs nothing after the impactor has left the plate (rebound, or perforation with the
// force back to zero), so the run stops there instead of at a termination_time long enough for the
// slowest case. The force is the contact's resultant on its side A after each cycle's force pass
// (its magnitude, or the absolute value of one global component with DOF 1-3). The start of the
// current force-free stretch is run state (restart dumps), so a continued run stops where an
// uninterrupted one does.
#pragma once

#include <string>

#include "config/scene.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

class ContactTermination : public RunObserver {
 public:
  explicit ContactTermination(const config::TerminationContactSpec& spec) : spec_(spec) {}
  void start(const solver::Solver& solver) override;
  void resume(const solver::Solver& solver) override { start(solver); }
  void visit_state(StateVisitor& visitor) override;
  void after_cycle(const solver::Solver& solver) override;
  std::string termination() const override { return reason_; }

 private:
  config::TerminationContactSpec spec_;
  std::size_t contact_ = 0;
  double quiet_since_ = -1;  // s, start of the current stretch at or below THRES (-1: none)
  std::string reason_;       // set once the rule is met
};

}  // namespace plyimpact::run
