// Quantities of interest of one finished run, computed from its history.csv and summary.json and
// looked up by name in one table (quantity_table()); adding a quantity is one function and one
// table row. A quantity may expand into several values (eroded elements by cause, delaminated area
// per interface). When the scene cannot provide a quantity (no rigid impactor, no delamination
// columns, nothing erodes), its function throws NotAvailable with the reason, which the study table
// reports instead of a number.
#pragma once

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "output/history_table.hpp"
#include "output/json.hpp"

namespace plyimpact::study {

struct RunRecord {
  output::HistoryTable history{{"time"}};
  output::Json summary;  // summary.json
  // Travel of the impactor's centre of mass that puts its undeformed nose beyond the rear face of
  // the undeformed plate (gap + plate thickness, m), from the case's scene; NaN without a laminate
  // and an impactor. Used by the perforation criterion (ballistic_limit.hpp).
  double pass_distance = std::nan("");
};

/// Per history row: time, the impactor's travel and velocity along the impact direction (its
/// initial velocity), from a rigid impactor's columns or a deformable one's centre of mass.
/// @throws NotAvailable
struct ImpactorTrack {
  std::vector<double> time, travel, velocity;
};
ImpactorTrack impactor_track(const RunRecord& r);

/// The rigid impactor's axial force as its load cell would read it: the momentum it lost along the
/// impact direction over each history interval, over the interval (the interval's mean force, which
/// contact ringing faster than the rows cannot alias into, as it does into an instantaneous
/// sample), at the intervals' middles, resampled on a uniform grid of the median interval for the
/// CFC filter (channel_filter.hpp). Positive when it resists the impact. @throws NotAvailable
struct ImpactorForce {
  double interval = 0;  // s, the grid's spacing
  std::vector<double> time, force;
};
ImpactorForce impactor_force(const RunRecord& r);

struct QuantityValue {
  std::string name;  // the quantity's name, or name_<suffix> for an expanded quantity
  double value;      // SI
};

class NotAvailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using QuantityFunction = std::vector<QuantityValue> (*)(const RunRecord&);

struct QuantityDefinition {
  std::string_view name;
  std::string_view unit;         // SI unit of the values
  std::string_view description;  // one line, for usage text and study.json
  QuantityFunction compute;
};

/// Every quantity, in the order of the usage text.
std::span<const QuantityDefinition> quantity_table();

/// The named quantity, or nullptr.
const QuantityDefinition* find_quantity(std::string_view name);

/// Names of all quantities, for "allowed ..." messages.
std::vector<std::string> quantity_names();

/// Reads <case_dir>/history.csv and <case_dir>/summary.json. @throws InputError
RunRecord read_run_record(const std::string& case_dir);

}  // namespace plyimpact::study
