#include "apps/interrupt.h"

#include <csignal>

#include "lib/common/assert.h"

namespace insmc::app {
namespace {

// Lock-free atomics: storing to them is async-signal-safe.
std::atomic<int> g_signal{0};
std::atomic<std::atomic<bool>*> g_stop{nullptr};
struct sigaction g_old_int, g_old_term;

extern "C" void on_signal(int signal) {
  g_signal.store(signal);
  if (std::atomic<bool>* stop = g_stop.load()) stop->store(true);
}

}  // namespace

InterruptGuard::InterruptGuard(std::atomic<bool>& stop) {
  static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free &&
                std::atomic<std::atomic<bool>*>::is_always_lock_free);
  INSMC_ASSERT(g_stop.load() == nullptr, "two InterruptGuards at once");
  g_signal.store(0);
  g_stop.store(&stop);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &g_old_int);
  sigaction(SIGTERM, &action, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
  g_stop.store(nullptr);
}

int InterruptGuard::signal_received() { return g_signal.load(); }

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "a signal";
  }
}

}  // namespace insmc::app
