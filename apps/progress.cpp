#include "apps/progress.h"

#include <cstdio>
#include <fmt/core.h>
#include <unistd.h>

namespace insmc::app {

Progress::Progress(std::uint64_t total)
    : total_(total), enabled_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() {
  if (printed_) fmt::print(stderr, "\r\033[K");
}

void Progress::update(std::uint64_t done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(mutex_);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0 || std::chrono::duration<double>(now - last_).count() < 0.25) return;
  last_ = now;
  const double rate = static_cast<double>(done) / elapsed;
  const double eta = rate > 0 ? static_cast<double>(total_ - done) / rate : 0.0;
  fmt::print(stderr, "\r{} / {} samples, {:.3g} samples/s, ETA {:.0f} s\033[K", done, total_, rate, eta);
  printed_ = true;
}

}  // namespace insmc::app
