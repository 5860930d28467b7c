// The hourglass check of a run: the largest share of the internal energy held in hourglass modes
// over the whole run, and a pass/fail against the limit (control.hourglass_warn_ratio, 10 % by
// default: the usual acceptance in LS-DYNA practice, hourglass energy below about a tenth of the
// internal energy at every time). The share at time t is
//   hourglass(t) / max(internal(t), kFloor x reference(t)),
// reference = initial total energy + external work (the energy ratio's reference): the internal
// energy of the same time, as the rule states, on a denominator that cannot be ~0. At first
// contact the internal energy is round-off (1e-37 J) and a plain ratio reads millions of per cent;
// with the floor (1 % of the run's energy), hourglass energy that is a negligible part of the run
// cannot fail the check, while one that reaches the limit's share of the internal energy (once
// that is a real part of the run) or of 1 % of the run's energy does. Sampled with the history
// rows, so the maximum is over those samples.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/state_visitor.hpp"

namespace plyimpact::run {

// The check's result for summary.json: the largest share, when, what it was made of, the limit.
struct HourglassVerdict {
  double max_ratio = 0, time = 0, hourglass = 0, denominator = 0, limit = 0;
  double eroded_hourglass = 0;  // J, the part of `hourglass` that eroded elements held when deleted
  bool floor_governs = false;  // the denominator at the maximum was the floor, not the internal energy
  bool passed = true;          // max_ratio <= limit
  // J at the maximum, per part (model::Model::parts order), live and eroded elements: where the
  // hourglass energy is (LS-DYNA's per-part MATSUM answers the same question). Empty: not recorded.
  std::vector<double> by_part;
};

class HourglassWatch {
 public:
  static constexpr double kFloor = 0.01;  // of the reference energy

  explicit HourglassWatch(double warn_ratio) : warn_ratio_(warn_ratio) {}

  // hourglass, internal, reference: J at time t (s); eroded_hourglass: the part of `hourglass` that
  // eroded elements held (reported with the maximum: the check counts it, as LS-DYNA's totals do).
  // Returns whether this sample is the new maximum (the caller may then record_by_part).
  bool observe(double t, double hourglass, double internal, double reference, double eroded_hourglass = 0);
  // The parts' names (model order), for the warning to say where the hourglass energy is.
  void name_parts(std::vector<std::string> names) { part_names_ = std::move(names); }
  // The hourglass energy of each part at the sample observe just found to be the maximum.
  void record_by_part(const std::vector<double>& joules) { by_part_ = joules; }

  bool exceeded() const { return max_ratio_ > warn_ratio_; }
  double max_ratio() const { return max_ratio_; }
  HourglassVerdict verdict() const;
  // The warning text (empty when not exceeded): the ratio, when, and the rule.
  std::string warning() const;
  // The extremes so far (run state: a continued run checks as the uninterrupted one).
  void visit_state(StateVisitor& visitor);

 private:
  double warn_ratio_;
  double max_ratio_ = 0;
  double time_ = 0, hourglass_ = 0, denominator_ = 0, eroded_hourglass_ = 0;  // at the largest ratio
  bool floor_governs_ = false;
  std::vector<double> by_part_;          // at the largest ratio, J per part
  std::vector<std::string> part_names_;  // not run state: the model's
};

}  // namespace plyimpact::run
