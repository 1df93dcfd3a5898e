#pragma once
/// Wall-clock helpers shared by the throughput measurements.
#include <atomic>
#include <chrono>

namespace insmc::mc::bench {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Stores a result where the optimizer must assume it is read, so a timed
/// loop whose results are otherwise unused is not dropped. Atomic because
/// worker threads call it concurrently.
inline void keep(double value) {
  static std::atomic<double> sink{0.0};
  sink.store(value, std::memory_order_relaxed);
}

}  // namespace insmc::mc::bench
