#pragma once
/// Progress on stderr (count, rate and ETA) for work longer than a second,
/// only when stderr is a terminal; silent otherwise (scripts, CI, pipes).
/// The environment variable INSMC_PROGRESS=always prints it anyway, from
/// the start, a line per update where stderr is not a terminal (a CI log);
/// INSMC_PROGRESS=never silences it on a terminal too.
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>

namespace insmc::app {

class Progress {
 public:
  /// `unit` names what is counted ("samples", "runs", "files").
  explicit Progress(std::uint64_t total, std::string unit = "samples");
  ~Progress();
  void update(std::uint64_t done);
  /// Progress of a command of several stages, each with a count of its own
  /// (a new stage name starts its own rate and ETA).
  void update(std::string_view stage, std::uint64_t done, std::uint64_t total, std::string_view unit);

 private:
  std::uint64_t total_;
  std::string unit_, stage_;
  bool enabled_, always_, terminal_;
  /// last_: the last line printed; heard_: the last update of any stage
  /// (a new stage's work began then, not at its first report).
  std::chrono::steady_clock::time_point start_, stage_start_, last_, heard_;
  std::mutex mutex_;
  bool printed_ = false;
};

}  // namespace insmc::app
