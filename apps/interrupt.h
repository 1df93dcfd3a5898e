#pragma once
/// SIGINT and SIGTERM during a checkpointed run: instead of dying, the run
/// stops between two blocks, writes its checkpoint and exits 128 + signal.
#include <atomic>

namespace insmc::app {

/// While alive, SIGINT and SIGTERM set `stop` (the engine's cancellation
/// flag, which must outlive the guard) and record the signal. A second
/// signal of the same kind gets the default action (SA_RESETHAND), so a
/// second Ctrl-C still kills a run that is slow to stop. The destructor
/// restores the previous handlers. One guard at a time.
class InterruptGuard {
 public:
  explicit InterruptGuard(std::atomic<bool>& stop);
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The signal received (SIGINT, SIGTERM), or 0.
  static int signal_received();
};

/// "SIGINT", "SIGTERM" (or "a signal" for any other).
const char* signal_name(int signal);

}  // namespace insmc::app
