#include "run/stop_signals.hpp"

#include <cstring>

#include "core/error.hpp"

namespace plyimpact::run {

namespace {

volatile std::sig_atomic_t g_received = 0;
volatile std::sig_atomic_t g_installed = 0;  // only touched outside handlers

extern "C" void on_stop_signal(int signal) { g_received = signal; }

}  // namespace

StopSignals::StopSignals() {
  if (g_installed) throw RunError("internal: the stop-signal handlers are already installed");
  g_received = 0;
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: a signal arriving during a write() of an output does not turn it into an error.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
  g_installed = 1;
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
  g_installed = 0;
}

int StopSignals::received() { return g_received; }

std::string StopSignals::name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

}  // namespace plyimpact::run
