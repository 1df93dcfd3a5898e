#include "montecarlo/records/runs/files/filter_windows.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace insmc::runs {
namespace {

/// The time stamps' jitter allowed, as a share of τ.
constexpr double kJitter = 0.01;

/// Blocks of n windows of τ: the smallest n with n·τ ≥ min_tau_s that
/// divides T/τ when that is whole (the test run's last block then ends at T),
/// up to twice the least; else the least (a block across T is left out).
int block_factor(double tau_s, double test_duration_s, double min_tau_s) {
  const int least = static_cast<int>(std::ceil(min_tau_s / tau_s * (1 - 1e-9)));
  const double windows = test_duration_s / tau_s;
  const long whole = std::lround(windows);
  if (std::abs(windows - static_cast<double>(whole)) > 1e-6 * windows) return least;
  for (long n = least; n <= std::min<long>(2L * least, whole); ++n)
    if (whole % n == 0) return static_cast<int>(n);
  return least;
}

}  // namespace

FilterWindows coarsen_filter_windows(RecordFile& file, double tau_s, double test_duration_s, double min_tau_s) {
  FilterWindows out{tau_s, 1, 0};
  if (!(tau_s > 0) || tau_s >= min_tau_s * (1 - 1e-9)) return out;
  const int n = block_factor(tau_s, test_duration_s, min_tau_s);
  const double block_s = n * tau_s;
  out.tau_s = block_s;
  out.factor = n;
  for (RecordRun& run : file.runs) {
    for (int k = 0; k < 3; ++k) {
      // The block under way: its index on the τ' grid, phase, values and last row.
      long block = -1;
      Phase phase = Phase::kTest;
      int count = 0;
      double sum = 0.0, last_t = 0.0;
      bool broken = false;
      OptionalValue* last_value = nullptr;
      const auto close = [&] {
        if (!last_value) return;
        if (!broken && count == n) {
          *last_value = sum / n;
        } else {
          *last_value = std::nullopt;
          out.dropped += count;
        }
        last_value = nullptr;
      };
      for (RecordRow& row : run.rows) {
        OptionalValue& value = row.f_mps2[static_cast<std::size_t>(k)];
        if (!value || row.phase == Phase::kAlign) continue;
        // Window (t − τ, t] lies in block ceil(t/τ'): blocks of one grid. A
        // recorder's time stamps may jitter by up to 1 % of τ.
        const long b = std::lround(std::ceil((row.t_s - kJitter * tau_s) / block_s));
        if (b != block || row.phase != phase) {
          close();
          block = b;
          phase = row.phase;
          count = 0;
          sum = 0.0;
          broken = false;
        } else {
          broken |= std::abs(row.t_s - last_t - tau_s) > 2 * kJitter * tau_s;
          *last_value = std::nullopt;  // only the block's last row keeps a value
        }
        sum += *value;
        ++count;
        last_t = row.t_s;
        last_value = &value;
      }
      close();
    }
  }
  return out;
}

}  // namespace insmc::runs
