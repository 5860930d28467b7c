// Watch on the sign of each contact's energy (run summary warning). A penalty contact stores
// energy in its springs and dissipates it by friction and damping; it cannot give the bodies more
// than it has taken from them. A contact energy below zero therefore means the contact model
// created energy (a spring that appeared already compressed and pushed the bodies apart), which
// LS-DYNA users look for in the GLSTAT/SLEOUT contact energy. The watch warns when the energy of a
// contact first falls below -1 % of the reference energy (the initial total energy plus the
// external work: the energy ratio's reference), naming the contact, the time it first crossed and
// the lowest value reached. Checked every cycle, so a short dip between history samples counts.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/state_visitor.hpp"

namespace plyimpact::run {

class ContactEnergyWatch {
 public:
  static constexpr double kFraction = 0.01;  // of the reference energy

  explicit ContactEnergyWatch(std::vector<std::string> names);

  // energies[c]: energy of contact c (J) at time t (s); reference: J (<= 0: nothing is checked).
  void observe(const std::vector<double>& energies, double t, double reference);

  // One warning per contact that crossed the threshold.
  std::vector<std::string> warnings() const;

  // What has been seen so far, per contact (run state for a restart).
  void visit_state(StateVisitor& visitor);

 private:
  struct Entry {
    std::string name;
    double first_time = -1;  // s, first time below the threshold; < 0: never
    double threshold = 0;    // J, the threshold at that time
    double minimum = std::numeric_limits<double>::infinity();  // J, lowest energy after crossing
    double minimum_time = 0;
  };
  std::vector<Entry> entries_;
};

}  // namespace plyimpact::run
