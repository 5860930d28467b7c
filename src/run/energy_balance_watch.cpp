#include "run/energy_balance_watch.hpp"

#include <cstdio>

namespace plyimpact::run {

void EnergyBalanceWatch::observe(const solver::Energies& balance, double ratio, double reference, long cycle) {
  if (cycle < kSkipCycles) return;
  const double t = balance.time;
  if (ratio < ratio_min_) ratio_min_ = ratio, time_of_min_ = t;
  if (ratio > ratio_max_) ratio_max_ = ratio, time_of_max_ = t;
  if (keys_.empty())
    for (const auto& term : balance.terms)
      if (term.owner >= 0) keys_.push_back(term.key);
  if (lowest_share_.size() != keys_.size()) {  // first sample (a restart has them from the dump)
    lowest_share_.assign(keys_.size(), 0.0);
    lowest_value_.assign(keys_.size(), 0.0);
    time_of_lowest_.assign(keys_.size(), 0.0);
  }
  std::size_t k = 0;
  for (const auto& term : balance.terms) {
    if (term.owner < 0) continue;
    const double share = reference > 0 ? term.value / reference : 0.0;
    if (share < lowest_share_[k]) lowest_share_[k] = share, lowest_value_[k] = term.value, time_of_lowest_[k] = t;
    ++k;
  }
}

EnergyBalanceVerdict EnergyBalanceWatch::verdict() const {
  EnergyBalanceVerdict v;
  v.ratio_min = ratio_min_, v.time_of_min = time_of_min_;
  v.ratio_max = ratio_max_, v.time_of_max = time_of_max_;
  v.tolerance = kRatioTolerance;
  for (std::size_t k = 0; k < keys_.size() && k < lowest_share_.size(); ++k)
    if (lowest_share_[k] < -kNegativeTolerance) v.negative.push_back({keys_[k], lowest_value_[k], time_of_lowest_[k]});
  v.passed = ratio_min_ >= 1 - kRatioTolerance && ratio_max_ <= 1 + kRatioTolerance && v.negative.empty();
  return v;
}

std::vector<std::string> EnergyBalanceWatch::warnings() const {
  const EnergyBalanceVerdict v = verdict();
  std::vector<std::string> out;
  char line[400];
  if (v.ratio_min < 1 - v.tolerance || v.ratio_max > 1 + v.tolerance) {
    std::snprintf(line, sizeof line,
                  "energy ratio left 1 +- %g: between %.5f (t = %.4g s) and %.5f (t = %.4g s); the run lost or "
                  "created energy (history.csv: energy_ratio and the terms of the balance show which)",
                  v.tolerance, v.ratio_min, v.time_of_min, v.ratio_max, v.time_of_max);
    out.push_back(line);
  }
  for (const NegativeEnergy& n : v.negative) {
    std::snprintf(line, sizeof line,
                  "%s energy went negative: %.4g J at t = %.4g s; the contributor gave the bodies energy nobody "
                  "put in (for a contact: penetrations or a too soft penalty)",
                  n.key.c_str(), n.value, n.time);
    out.push_back(line);
  }
  return out;
}

void EnergyBalanceWatch::visit_state(StateVisitor& visitor) {
  visitor.scalar("ratio_min", ratio_min_);
  visitor.scalar("time_of_min", time_of_min_);
  visitor.scalar("ratio_max", ratio_max_);
  visitor.scalar("time_of_max", time_of_max_);
  visitor.array("lowest_share", lowest_share_);
  visitor.array("lowest_value", lowest_value_);
  visitor.array("time_of_lowest", time_of_lowest_);
}

}  // namespace plyimpact::run
