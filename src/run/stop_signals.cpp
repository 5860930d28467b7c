#include "run/stop_signals.hpp"

#include <atomic>

#include "core/error.hpp"

namespace plyimpact::run {

namespace {

// A lock-free atomic is async-signal-safe (C++17 [support.signal]) and, unlike a volatile
// sig_atomic_t, also well defined when the handler runs on an OpenMP worker thread while the main
// thread reads the flag.
std::atomic<int> g_received{0};
static_assert(std::atomic<int>::is_always_lock_free);
bool g_installed = false;  // only touched outside handlers

extern "C" void on_stop_signal(int signal) { g_received.store(signal, std::memory_order_relaxed); }

}  // namespace

StopSignals::StopSignals() {
  if (g_installed) throw RunError("internal: the stop-signal handlers are already installed");
  g_received.store(0);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: a signal arriving during a write() of an output does not turn it into an error.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
  g_installed = true;
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
  g_installed = false;
}

int StopSignals::received() { return g_received.load(std::memory_order_relaxed); }

std::string StopSignals::name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

}  // namespace plyimpact::run
