// *TERMINATION_CONTACT. See contact_termination.hpp.
#include "run/contact_termination.hpp"

#include <cmath>

#include "core/error.hpp"
#include "model/subsystems.hpp"

namespace plyimpact::run {

void ContactTermination::start(const solver::Solver& solver) {
  const auto& contacts = solver.contacts();
  for (contact_ = 0; contact_ < contacts.size(); ++contact_)
    if (contacts[contact_].name() == spec_.contact) return;
  throw RunError(msg() << "termination_contact names contact '" << spec_.contact << "', which the model does not have");
}

void ContactTermination::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "termination_contact");
  visitor.scalar("quiet_since", quiet_since_);
}

void ContactTermination::after_cycle(const solver::Solver& solver) {
  const double t = solver.state().time;
  if (t < spec_.ACTIM || !reason_.empty()) return;
  const Vec3& r = solver.contacts()[contact_].forces().resultant;
  const double force = spec_.DOF == 0 ? std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) : std::abs(r[spec_.DOF - 1]);
  if (force > spec_.THRES) {
    quiet_since_ = -1;
    return;
  }
  if (quiet_since_ < 0) quiet_since_ = t;
  if (t - quiet_since_ >= spec_.DUR * (1 - 1e-12))
    reason_ = msg() << "termination_contact at t = " << t << " s: " << model::describe_termination_contact(spec_)
                    << ", since t = " << quiet_since_ << " s";
}

}  // namespace plyimpact::run
