// Progress line: time, cycle, step, wall time, ETA and energy ratio. On a terminal one line is
// updated in place (5 times a second); otherwise a line every 10 s of wall time (logs).
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

#include "run/run_observer.hpp"

namespace plyimpact::run {

// "12.3s", "4m05s" or, past 100 hours, "1.2e+03h"; "?" for a negative or non-finite duration (no
// estimate yet), never a wrapped-around integer.
std::string format_duration(double seconds);

class ProgressLine : public RunObserver {
 public:
  using Clock = std::chrono::steady_clock;
  ProgressLine(std::ostream& out, bool in_place, double t_end, Clock::time_point t_start)
      : out_(out), in_place_(in_place), t_end_(t_end), t_start_(t_start) {}
  void after_cycle(const solver::Solver& solver) override;
  std::string_view timing_name() const override { return "progress line"; }
  void stop(const solver::Solver* solver, RunReport& report) override;

 private:
  std::ostream& out_;
  bool in_place_;
  double t_end_;
  Clock::time_point t_start_;
  double next_ = 0;  // wall seconds of the next line
};

}  // namespace plyimpact::run
