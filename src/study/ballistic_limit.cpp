// Ballistic limit search. See ballistic_limit.hpp.
#include "study/ballistic_limit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace plyimpact::study {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string describe(const Shot& s) {
  return number(s.velocity) + " (residual velocity " + number(s.residual) + " m/s" +
         (s.case_name.empty() ? "" : ", case " + s.case_name) + ")";
}

// Narrows [lo, hi] with shots inside it: hi to the lowest perforation, lo to the highest stop below
// it. Stops above the lowest perforation are a zone of mixed results, noted.
void narrow(BallisticLimit& b, const std::vector<Shot>& shots) {
  for (const Shot& s : shots)
    if (s.state == Perforation::perforated && s.velocity > b.lo && s.velocity < b.hi) b.hi = s.velocity;
  for (const Shot& s : shots) {
    if (s.state != Perforation::stopped) continue;
    if (s.velocity > b.lo && s.velocity < b.hi) b.lo = s.velocity;
    else if (s.velocity >= b.hi)
      b.notes.push_back("mixed results: stopped at " + describe(s) + " above a perforation at " + number(b.hi) +
                        "; the bracket kept is the one below the lowest perforation");
  }
}

[[noreturn]] void undecided(const BracketSearch& q, const Shot& s) {
  throw InputError(msg() << q.origin << ": the run at " << describe(s)
                         << " is undecided: the impactor still moves forward in contact with the plate at the end; "
                            "allowed a control.termination_time (under set:) long enough for it to stop or fly free");
}

}  // namespace

const char* const kPerforationCriterion =
    "perforated: at the end of the run the impactor moves on along the impact direction (residual velocity > 0), "
    "flies free (its centre-of-mass velocity changed by less than 1 % of the impact velocity over the last tenth "
    "of the run) and its centre of mass has travelled at least gap + plate thickness; stopped: its velocity along "
    "the impact direction reached zero at some time (arrested or rebounding); otherwise undecided (the run is too short)";

const char* perforation_name(Perforation p) {
  switch (p) {
    case Perforation::perforated: return "perforated";
    case Perforation::stopped: return "stopped";
    case Perforation::undecided: return "undecided";
  }
  return "undecided";
}

Perforation classify(const RunRecord& r, double pass_distance) {
  if (!std::isfinite(pass_distance))
    throw NotAvailable("not available in this scene: perforation needs a laminate and an impactor (gap + plate thickness)");
  const ImpactorTrack t = impactor_track(r);
  const std::size_t n = t.time.size();
  // Arrested once, arrested for good: the plate can push a resting impactor back, never through.
  if (*std::min_element(t.velocity.begin(), t.velocity.end()) <= 0) return Perforation::stopped;
  const double v_end = t.velocity.back();
  // Free flight over the last tenth of the run: the centre-of-mass velocity is constant.
  const double t_from = t.time.back() - 0.1 * (t.time.back() - t.time.front());
  double v_min = v_end, v_max = v_end;
  for (std::size_t i = n; i-- > 0 && t.time[i] >= t_from;) {
    v_min = std::min(v_min, t.velocity[i]);
    v_max = std::max(v_max, t.velocity[i]);
  }
  const bool free_flight = v_max - v_min < 1e-2 * std::abs(t.velocity.front());
  return free_flight && t.travel.back() >= pass_distance ? Perforation::perforated : Perforation::undecided;
}

BallisticLimit search_ballistic_limit(const BracketSearch& q, const ShotFunction& shoot,
                                      const std::vector<Shot>& known) {
  if (!(q.lo < q.hi) || !(q.tolerance > 0))
    throw InputError(msg() << q.origin << ": a bracket [lo, hi] with lo < hi and a positive tolerance is needed; found ["
                           << number(q.lo) << ", " << number(q.hi) << "], tolerance " << number(q.tolerance));
  BallisticLimit b;
  b.lo = q.lo;
  b.hi = q.hi;
  b.shots = shoot({q.lo, q.hi});
  const Shot &low = b.shots.at(0), &high = b.shots.at(1);
  if (low.state == Perforation::undecided) undecided(q, low);
  if (high.state == Perforation::undecided) undecided(q, high);
  if (low.state != Perforation::stopped || high.state != Perforation::perforated)
    throw InputError(msg() << q.origin << ": the bracket does not bracket the ballistic limit: " << number(q.lo) << " "
                           << perforation_name(low.state) << " " << describe(low) << ", " << number(q.hi) << " "
                           << perforation_name(high.state) << " " << describe(high)
                           << "; allowed a bracket whose low end stops the impactor and whose high end perforates");
  narrow(b, known);
  const int points = std::max(1, q.points);
  while (b.hi - b.lo > q.tolerance) {
    std::vector<double> v;
    for (int i = 1; i <= points; ++i) v.push_back(b.lo + (b.hi - b.lo) * i / (points + 1));
    const std::vector<Shot> round = shoot(v);
    for (const Shot& s : round) {
      if (s.state == Perforation::undecided) undecided(q, s);
      b.shots.push_back(s);
    }
    const double width = b.hi - b.lo;
    narrow(b, round);
    ++b.rounds;
    if (b.hi - b.lo >= width)  // the velocities were rounded onto the bracket's ends
      throw InputError(msg() << q.origin << ": the bracket [" << number(b.lo) << ", " << number(b.hi)
                             << "] cannot be narrowed further at the values' resolution; allowed a tolerance above "
                             << number(width));
  }
  b.limit = 0.5 * (b.lo + b.hi);
  return b;
}

}  // namespace plyimpact::study
