#include "run/run_timing.hpp"

#include <algorithm>
#include <cstdio>

namespace plyimpact::run {

void RunTiming::add(std::string_view name, double seconds) {
  for (auto& r : rows_)
    if (r.name == name) {
      r.seconds += seconds;
      return;
    }
  rows_.push_back({std::string(name), seconds});
}

double RunTiming::accounted() const {
  double sum = 0;
  for (const auto& r : rows_) sum += r.seconds;
  return sum;
}

std::string timing_table(const RunTiming& timing) {
  std::vector<TimingRow> rows = timing.rows();
  std::stable_sort(rows.begin(), rows.end(), [](const TimingRow& a, const TimingRow& b) { return a.seconds > b.seconds; });
  std::string out;
  char buf[160];
  const double span = timing.span > 0 ? timing.span : 1;
  for (const auto& r : rows) {
    std::snprintf(buf, sizeof buf, "  %-30s %9.2f s %6.1f %%\n", r.name.c_str(), r.seconds, 100 * r.seconds / span);
    out += buf;
  }
  return out;
}

}  // namespace plyimpact::run
