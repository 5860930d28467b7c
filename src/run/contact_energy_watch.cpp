#include "run/contact_energy_watch.hpp"

#include <cstdio>

namespace plyimpact::run {

ContactEnergyWatch::ContactEnergyWatch(std::vector<std::string> names) {
  for (auto& n : names) entries_.push_back(Entry{std::move(n)});
}

void ContactEnergyWatch::observe(const std::vector<double>& energies, double t, double reference) {
  if (!(reference > 0)) return;
  for (std::size_t c = 0; c < entries_.size() && c < energies.size(); ++c) {
    Entry& e = entries_[c];
    if (e.first_time < 0) {
      if (!(energies[c] < -kFraction * reference)) continue;
      e.first_time = t;
      e.threshold = -kFraction * reference;
    }
    if (energies[c] < e.minimum) {
      e.minimum = energies[c];
      e.minimum_time = t;
    }
  }
}

void ContactEnergyWatch::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "contact_energy_watch");
  for (Entry& e : entries_) {
    StateGroup contact(visitor, e.name);
    visitor.scalar("first_time", e.first_time);
    visitor.scalar("threshold", e.threshold);
    visitor.scalar("minimum", e.minimum);
    visitor.scalar("minimum_time", e.minimum_time);
  }
}

std::vector<std::string> ContactEnergyWatch::warnings() const {
  std::vector<std::string> out;
  for (const Entry& e : entries_) {
    if (e.first_time < 0) continue;
    char w[400];
    std::snprintf(w, sizeof w,
                  "contact '%s': contact energy negative, below %.4g J (%.0f%% of the reference energy) from t = %.4g s, "
                  "minimum %.4g J at %.4g s: the contact gave the bodies more energy than its springs stored",
                  e.name.c_str(), e.threshold, 100 * kFraction, e.first_time, e.minimum, e.minimum_time);
    out.push_back(w);
  }
  return out;
}

}  // namespace plyimpact::run
