#pragma once
/// Progress on stderr (samples/s and ETA) for runs longer than a second,
/// only when stderr is a terminal; silent otherwise.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>

namespace insmc::app {

class Progress {
 public:
  explicit Progress(std::uint64_t total);
  ~Progress();
  void update(std::uint64_t done);

 private:
  std::uint64_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_;
  std::mutex mutex_;
  bool printed_ = false;
};

}  // namespace insmc::app
