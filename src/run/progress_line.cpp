#include "run/progress_line.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace plyimpact::run {

std::string format_duration(double s) {
  char buf[32];
  if (!(s >= 0) || !std::isfinite(s)) return "?";  // no estimate yet (or a broken clock)
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1fs", s);
  else if (s < 100 * 3600.0) std::snprintf(buf, sizeof buf, "%ldm%02lds", long(s / 60), long(s) % 60);
  else std::snprintf(buf, sizeof buf, "%.3gh", s / 3600);  // beyond 100 hours whole minutes say nothing
  return buf;
}

void ProgressLine::after_cycle(const solver::Solver& solver) {
  const solver::State& s = solver.state();
  const double t = s.time;
  const bool last = t >= t_end_ * (1 - 1e-12);
  const double wall = std::chrono::duration<double>(Clock::now() - t_start_).count();
  if (!(wall >= next_ || last)) return;
  const double pct = 100.0 * t / t_end_;
  const double eta = pct > 0 ? wall * (100.0 - pct) / pct : -1.0;  // -1: no estimate before time advances
  char line[200];
  std::snprintf(line, sizeof line, "t %.4e s (%5.1f%%)  cycle %ld  dt %.3e s  wall %s  ETA %s  energy ratio %.4f", t,
                pct, s.cycle, s.dt_prev_half, format_duration(wall).c_str(), format_duration(eta).c_str(),
                solver.energy_ratio());
  if (in_place_) {
    out_ << '\r' << line << "\033[K" << std::flush;
    next_ = wall + 0.2;
  } else {
    out_ << line << '\n' << std::flush;
    next_ = wall + 10.0;
  }
}

void ProgressLine::stop(const solver::Solver* solver, RunReport& report) {
  (void)solver;
  (void)report;
  if (in_place_) out_ << '\n';
}

}  // namespace plyimpact::run
