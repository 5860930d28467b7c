// The energy-balance check of a run, over the whole run rather than at its end:
//   - the energy ratio (total / (initial total + external work)) stays within 1 +- kRatioTolerance
//     at every history sample: 1 % is what this project holds its scenes to (an explicit run that
//     conserves energy to the scheme's O(dt^2) stays well inside it; contact or erosion defects
//     that create or destroy energy leave it, docs/theory.md section 11);
//   - no energy of a force contributor (contact, friction, rigid wall, interfaces, tiebreaks: all
//     stored or dissipated energies) goes negative: a negative contact or interface energy means
//     the contributor gave the bodies energy nobody put in (LS-DYNA practice reads negative sliding
//     energy the same way). "Negative" is below -kNegativeTolerance of the run's reference energy:
//     these terms are sums of non-negative increments up to round-off, which stays many orders
//     below that.
// The first kSkipCycles cycles are not sampled: with the start-up half step their ratio is noise
// (the solver's own energy guard skips them too).
#pragma once

#include <string>
#include <vector>

#include "core/state_visitor.hpp"
#include "solver/energies.hpp"

namespace plyimpact::run {

// The most negative value a contributor's energy reached, and when.
struct NegativeEnergy {
  std::string key;  // the term's summary.json key
  double value = 0, time = 0;
};

// The check's result for summary.json.
struct EnergyBalanceVerdict {
  double ratio_min = 1, time_of_min = 0, ratio_max = 1, time_of_max = 0, tolerance = 0;
  std::vector<NegativeEnergy> negative;  // terms that went below the tolerance
  bool passed = true;
};

class EnergyBalanceWatch {
 public:
  static constexpr double kRatioTolerance = 0.01;
  static constexpr double kNegativeTolerance = 1e-6;  // of the reference energy
  static constexpr long kSkipCycles = 3;

  // One sample: the balance at its time, its ratio, the reference energy (J) and the cycle.
  void observe(const solver::Energies& balance, double ratio, double reference, long cycle);

  EnergyBalanceVerdict verdict() const;
  // One line per failed rule (empty when the check passed).
  std::vector<std::string> warnings() const;
  // The extremes so far (run state: a continued run checks as the uninterrupted one).
  void visit_state(StateVisitor& visitor);

 private:
  double ratio_min_ = 1, time_of_min_ = 0, ratio_max_ = 1, time_of_max_ = 0;
  std::vector<std::string> keys_;  // contributor terms, in balance order (from the first sample)
  // Per term: the lowest value over the reference energy, that value (J) and when.
  std::vector<double> lowest_share_, lowest_value_, time_of_lowest_;
};

}  // namespace plyimpact::run
