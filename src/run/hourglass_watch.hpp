// The hourglass-energy warning's rule. The hourglass energy is compared with the internal energy,
// as in LS-DYNA practice (HG below ~10 % of IE), but on a denominator that cannot be ~0: the
// larger of the peak internal energy so far and a floor of kFloor (1 %) of the reference energy
// (initial total energy + external work, the energy ratio's reference). At first contact the
// internal energy is round-off (1e-37 J) and a plain ratio reads millions of per cent; with the
// floor, hourglass energy that is a negligible part of the run cannot raise the warning, while
// one that reaches the stated share of the internal energy (once that is a real part of the run)
// or of 1 % of the run's energy does.
#pragma once

#include <string>

#include "core/state_visitor.hpp"

namespace plyimpact::run {

class HourglassWatch {
 public:
  static constexpr double kFloor = 0.01;  // of the reference energy

  explicit HourglassWatch(double warn_ratio) : warn_ratio_(warn_ratio) {}

  // hourglass, internal, reference: J at time t (s).
  void observe(double t, double hourglass, double internal, double reference);

  bool exceeded() const { return max_ratio_ > warn_ratio_; }
  double max_ratio() const { return max_ratio_; }
  // The warning text (empty when not exceeded): the ratio, when, and the rule.
  std::string warning() const;
  // The extremes so far (run state: a continued run warns as the uninterrupted one).
  void visit_state(StateVisitor& visitor);

 private:
  double warn_ratio_;
  double peak_internal_ = 0, max_ratio_ = 0;
  double time_ = 0, hourglass_ = 0, denominator_ = 0;  // at the largest ratio
  bool floor_governs_ = false;
};

}  // namespace plyimpact::run
