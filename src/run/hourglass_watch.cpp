#include "run/hourglass_watch.hpp"

#include <algorithm>
#include <cstdio>

namespace plyimpact::run {

void HourglassWatch::observe(double t, double hourglass, double internal, double reference) {
  const double floor = reference > 0 ? kFloor * reference : 0.0;
  const double denominator = std::max(internal, floor);
  if (!(denominator > 0)) return;
  const double ratio = hourglass / denominator;
  if (ratio > max_ratio_) {
    max_ratio_ = ratio;
    time_ = t;
    hourglass_ = hourglass;
    denominator_ = denominator;
    floor_governs_ = floor > internal;
  }
}

HourglassVerdict HourglassWatch::verdict() const {
  return {max_ratio_, time_, hourglass_, denominator_, warn_ratio_, floor_governs_, !exceeded()};
}

std::string HourglassWatch::warning() const {
  if (!exceeded()) return {};
  char w[480];
  std::snprintf(w, sizeof w,
                "hourglass energy reached %.1f%% of the %s (%.4g J of %.4g J at t = %.4g s; limit %.1f%%; rule: "
                "hourglass energy / max(internal energy, %.0f%% of the initial energy + external work), at "
                "every history sample): use IHQ 6, ELFORM 2 or more elements through the thickness",
                100 * max_ratio_, floor_governs_ ? "floor of 1% of the run's energy" : "internal energy", hourglass_,
                denominator_, time_, 100 * warn_ratio_, 100 * kFloor);
  return w;
}

void HourglassWatch::visit_state(StateVisitor& visitor) {
  visitor.scalar("max_ratio", max_ratio_);
  visitor.scalar("time_of_max", time_);
  visitor.scalar("hourglass_at_max", hourglass_);
  visitor.scalar("denominator_at_max", denominator_);
  visitor.scalar("floor_governs", floor_governs_);
}

}  // namespace plyimpact::run
