#include "interrupt.h"

#include <csignal>

namespace rtk::cli {

namespace {

// What a signal handler may touch: lock-free atomics (std::atomic<bool> and <int> are, on
// every platform RTK builds for).
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

struct sigaction g_previous_int, g_previous_term;

// [apps-interrupt]
extern "C" void on_stop_signal(int number) {
  g_signal.store(number, std::memory_order_relaxed);
  g_stop.store(true, std::memory_order_relaxed);
}
// [apps-interrupt]

}  // namespace

Interrupt::Interrupt() {
  g_stop = false;
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the first signal restores the default action, so a second one ends the
  // process at once; SA_RESTART: the system calls under way carry on.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

Interrupt::~Interrupt() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

const std::atomic<bool>* Interrupt::flag() const { return &g_stop; }
bool Interrupt::requested() const { return g_stop.load(std::memory_order_relaxed); }
int Interrupt::signal() const { return g_signal.load(std::memory_order_relaxed); }
const char* Interrupt::signal_name() const { return signal() == SIGTERM ? "SIGTERM" : "SIGINT"; }
int Interrupt::exit_status() const { return 128 + signal(); }

}  // namespace rtk::cli
