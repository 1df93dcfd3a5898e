#include "apps/progress.h"

#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <fmt/core.h>
#include <unistd.h>

namespace insmc::app {

namespace {

std::string_view progress_setting() {
  const char* v = std::getenv("INSMC_PROGRESS");
  return v ? std::string_view(v) : std::string_view();
}

}  // namespace

Progress::Progress(std::uint64_t total, std::string unit)
    : total_(total),
      unit_(std::move(unit)),
      always_(progress_setting() == "always"),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      stage_start_(start_),
      last_(start_),
      heard_(start_) {
  enabled_ = progress_setting() != "never" && (always_ || terminal_);
}

Progress::~Progress() {
  if (printed_ && terminal_) fmt::print(stderr, "\r\033[K");
}

void Progress::update(std::string_view stage, std::uint64_t done, std::uint64_t total, std::string_view unit) {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stage != stage_) {
      stage_ = stage;
      stage_start_ = heard_;
    }
    total_ = total;
    unit_ = unit;
  }
  update(done);
}

void Progress::update(std::uint64_t done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(mutex_);
  heard_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (!always_ && (elapsed < 1.0 || std::chrono::duration<double>(now - last_).count() < 0.25)) return;
  if (always_ && printed_ && done < total_ && std::chrono::duration<double>(now - last_).count() < 0.25) return;
  last_ = now;
  const double in_stage = std::chrono::duration<double>(now - stage_start_).count();
  const double rate = in_stage > 0 ? static_cast<double>(done) / in_stage : 0.0;
  const double eta = rate > 0 && total_ >= done ? static_cast<double>(total_ - done) / rate : 0.0;
  const std::string prefix = stage_.empty() ? std::string() : stage_ + ": ";
  const std::string line = fmt::format("{}{} / {} {}, {:.3g} {}/s, ETA {:.0f} s, {:.0f} s in all", prefix, done,
                                       total_, unit_, rate, unit_, eta, elapsed);
  // On a terminal one line, rewritten; in a log a line per update.
  if (terminal_)
    fmt::print(stderr, "\r{}\033[K", line);
  else
    fmt::print(stderr, "{}\n", line);
  printed_ = true;
}

}  // namespace insmc::app
