#include "run/hourglass_watch.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace plyimpact::run {

bool HourglassWatch::observe(double t, double hourglass, double internal, double reference, double eroded_hourglass) {
  const double floor = reference > 0 ? kFloor * reference : 0.0;
  const double denominator = std::max(internal, floor);
  if (!(denominator > 0)) return false;
  const double ratio = hourglass / denominator;
  if (!(ratio > max_ratio_)) return false;
  max_ratio_ = ratio;
  time_ = t;
  hourglass_ = hourglass;
  denominator_ = denominator;
  eroded_hourglass_ = eroded_hourglass;
  floor_governs_ = floor > internal;
  by_part_.clear();
  return true;
}

HourglassVerdict HourglassWatch::verdict() const {
  return {max_ratio_, time_, hourglass_, denominator_, warn_ratio_, eroded_hourglass_, floor_governs_, !exceeded(),
          by_part_};
}

std::string HourglassWatch::warning() const {
  if (!exceeded()) return {};
  char w[640];
  std::snprintf(w, sizeof w,
                "hourglass energy reached %.1f%% of the %s (%.4g J of %.4g J at t = %.4g s, %.4g J of it held by "
                "eroded elements; limit %.1f%%; rule: hourglass energy / max(internal energy, %.0f%% of the "
                "initial energy + external work), at every history sample): ",
                100 * max_ratio_, floor_governs_ ? "floor of 1% of the run's energy" : "internal energy", hourglass_,
                denominator_, time_, eroded_hourglass_, 100 * warn_ratio_, 100 * kFloor);
  // Mostly in deleted elements: deformation they carried in hourglass modes until they eroded
  // (crushed under an impactor), which no choice of IHQ for the live elements changes.
  const bool mostly_eroded = eroded_hourglass_ > 0.5 * hourglass_;
  std::string where;
  const auto most = std::max_element(by_part_.begin(), by_part_.end());
  if (most != by_part_.end() && *most > 0 && std::size_t(most - by_part_.begin()) < part_names_.size()) {
    char b[200];
    std::snprintf(b, sizeof b, "the most in part %s (%.3g J; summary.json: hourglass_check.by_part_at_max); ",
                  part_names_[std::size_t(most - by_part_.begin())].c_str(), *most);
    where = b;
  }
  return std::string(w) + where + (mostly_eroded ? "most of it was held by elements before they eroded (deformation carried in "
                                           "hourglass modes until deletion, as under an impactor); ELFORM 2 has no "
                                           "hourglass modes"
                                         : "use IHQ 6, ELFORM 2 or more elements through the thickness");
}

void HourglassWatch::visit_state(StateVisitor& visitor) {
  visitor.scalar("max_ratio", max_ratio_);
  visitor.scalar("time_of_max", time_);
  visitor.scalar("hourglass_at_max", hourglass_);
  visitor.scalar("denominator_at_max", denominator_);
  visitor.scalar("eroded_hourglass_at_max", eroded_hourglass_);
  visitor.scalar("floor_governs", floor_governs_);
  visitor.array("by_part_at_max", by_part_);
}

}  // namespace plyimpact::run
