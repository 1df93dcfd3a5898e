#pragma once
/// Wall-clock helpers shared by the throughput measurements.
#include <atomic>
#include <chrono>
#include <cstddef>

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

/// The floors' consumption of a block's outputs: sums of each value and its
/// square over `columns` columns of `rows` values (rows a multiple of 8),
/// in 8 independent lanes so that no scalar chain sets the pace.
inline double lane_sums(const double* y, std::size_t rows, std::size_t columns, std::size_t ld) {
  constexpr std::size_t kLanes = 8;
  double s1[kLanes] = {}, s2[kLanes] = {};
  for (std::size_t col = 0; col < columns; ++col) {
    const double* v = y + col * ld;
    for (std::size_t s = 0; s < rows; s += kLanes)
      for (std::size_t l = 0; l < kLanes; ++l) s1[l] += v[s + l], s2[l] += v[s + l] * v[s + l];
  }
  double total = 0;
  for (std::size_t l = 0; l < kLanes; ++l) total += s1[l] + s2[l];
  return total;
}

}  // namespace insmc::mc::bench
