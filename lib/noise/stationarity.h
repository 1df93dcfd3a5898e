#pragma once
/// Is the first part of each run (the warm-up, by default the first hour)
/// like the rest? (docs/noise.md §5.) With the noise model fitted to the
/// rest, the change of the channel's mean across the first part,
///   d = ȳ(last τ_b of the first part) − ȳ(first τ_b),  τ_b = first part / 6,
/// has variance (N.1) at lag (first part − τ_b) if the process is the same
/// throughout. Over R runs Σ z_r² ~ χ²(R); the first part is non-stationary
/// when that is above its 1 − α quantile. A warm-up shows as a drift of the
/// bias across the first part that the rest's noise does not explain.
#include <span>
#include <vector>

#include "lib/noise/noise_fit.h"
#include "lib/noise/recording.h"

namespace insmc::noise {

struct StationarityTest {
  bool tested = false;        ///< false when no run is at least twice the first part
  double first_part_s = 0, block_s = 0;
  std::size_t runs = 0;       ///< runs that entered the test
  double mean_change = 0;     ///< d averaged over the runs [SI]
  double expected_sd = 0;     ///< √(N.1) under the rest's model [SI]
  double statistic = 0;       ///< Σ z_r²
  double p_value = 1;
  bool stationary = true;
};

/// The first part of each run of at least 2 first_part_s, the channel y,
/// the kept segments (masked samples are left out of the averages).
StationarityTest test_first_part(std::span<const double> y, double dt_s, std::span<const Segment> runs,
                                 std::span<const Segment> kept, const NoiseModel& rest_model, double first_part_s,
                                 double alpha);

/// The kept segments with the first `first_part_s` of each run removed.
std::vector<Segment> after_first_part(std::span<const Segment> runs, std::span<const Segment> kept, double dt_s,
                                      double first_part_s);

}  // namespace insmc::noise
