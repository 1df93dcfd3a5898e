#include "apps/run_watch.h"

#include <atomic>
#include <optional>

#include "apps/interrupt.h"
#include "apps/progress.h"

namespace insmc::app {
namespace {

class TerminalWatch final : public mc::RunWatch {
 public:
  explicit TerminalWatch(bool stop_on_signals) {
    if (stop_on_signals) guard_.emplace(stop_);
  }
  void start(std::uint64_t samples) override { progress_.emplace(samples); }
  void progress(std::uint64_t done) override {
    if (progress_) progress_->update(done);
  }
  std::atomic<bool>* stop_flag() override { return guard_ ? &stop_ : nullptr; }
  int stop_signal() const override { return guard_ ? InterruptGuard::signal_received() : 0; }

 private:
  // Destroyed in reverse: the progress line is cleared, then the handlers
  // are restored, before the flag they set goes.
  std::atomic<bool> stop_{false};
  std::optional<InterruptGuard> guard_;
  std::optional<Progress> progress_;
};

}  // namespace

mc::RunOutcome run_study_watched(const mc::StudyConfig& config, const mc::StudyMap& map, mc::Processes& processes,
                                mc::StudyProgress start, mc::RunPlan plan, bool stop_on_signals) {
  TerminalWatch watch(stop_on_signals);
  plan.watch = &watch;
  return mc::run_study_blocks(config, map, processes, std::move(start), plan);
}

}  // namespace insmc::app
