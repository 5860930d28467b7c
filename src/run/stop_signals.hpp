// Clean stops on SIGINT (Ctrl-C) and SIGTERM (a batch system's or a user's kill): while a
// StopSignals object lives, the first such signal only sets a flag, which the run loop checks once
// per cycle and then ends the run like an early stop (history, the current frame, a restart dump
// and summary.json with status "interrupted"; exit code 2). The handler does nothing else because
// only async-signal-safe work is allowed in one (POSIX: writing a volatile sig_atomic_t is). It is
// installed with SA_RESETHAND, so a second signal finds the default action and kills the process
// at once: the way out when the orderly stop itself hangs. The flag is necessarily process-wide
// (a handler receives no context); one StopSignals may exist at a time.
#pragma once

#include <csignal>
#include <string>

namespace plyimpact::run {

class StopSignals {
 public:
  StopSignals();   // installs the handlers (throws RunError if another StopSignals is alive)
  ~StopSignals();  // restores the previous handlers
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal that asked for the stop, 0 while none has.
  static int received();
  // "SIGTERM", "SIGINT".
  static std::string name(int signal);

 private:
  struct sigaction previous_int_ {}, previous_term_ {};
};

}  // namespace plyimpact::run
