#include "run/progress_line.hpp"

#include <cstdio>
#include <ostream>
#include <string>

namespace plyimpact::run {

namespace {
std::string format_seconds(double s) {
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1fs", s);
  else std::snprintf(buf, sizeof buf, "%dm%02ds", int(s / 60), int(s) % 60);
  return buf;
}
}  // namespace

void ProgressLine::after_cycle(const solver::Solver& solver) {
  const solver::State& s = solver.state();
  const double t = s.time;
  const bool last = t >= t_end_ * (1 - 1e-12);
  const double wall = std::chrono::duration<double>(Clock::now() - t_start_).count();
  if (!(wall >= next_ || last)) return;
  const double pct = 100.0 * t / t_end_;
  const double eta = pct > 0 ? wall * (100.0 - pct) / pct : 0.0;
  char line[200];
  std::snprintf(line, sizeof line, "t %.4e s (%5.1f%%)  cycle %ld  dt %.3e s  wall %s  ETA %s  energy ratio %.4f", t,
                pct, s.cycle, s.dt_prev_half, format_seconds(wall).c_str(), format_seconds(eta).c_str(),
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
