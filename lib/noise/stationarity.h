#pragma once
/// Is the first part of each run (the warm-up, by default the first hour)
/// like the rest? (docs/noise.md §5.) With the noise model fitted to the
/// rest, the difference of the channel's means over the first part and over
/// the rest of a run,
///   d = ȳ(first part) − ȳ(rest),
/// each over its kept samples, is a combination Σ c_i θ(t_i) of the
/// integrated output at the kept stretches' ends with Σ c_i = 0 and
/// Σ c_i t_i = 0, so its variance follows from the model's structure
/// function D (lib/noise/noise_terms.h) whatever the gaps:
///   Var(d) = −½ Σ_i Σ_j c_i c_j D(t_i − t_j)                               (N.6)
/// ((N.1) is its case of two equal adjacent windows). If the process is the
/// same throughout, z = d/√Var(d) is standard normal and over R runs
/// Σ z_r² ~ χ²(R); the first part is non-stationary when that is above its
/// 1 − α quantile, so a stationary recording is flagged with probability α.
/// A warm-up shows as a first part whose mean sits off the rest's by more
/// than the rest's noise explains.
#include <span>
#include <vector>

#include "lib/noise/noise_fit.h"
#include "lib/noise/recording.h"

namespace insmc::noise {

struct StationarityTest {
  bool tested = false;        ///< false when no run is at least twice the first part
  double first_part_s = 0;
  std::size_t runs = 0;       ///< runs that entered the test
  double mean_change = 0;     ///< d averaged over the runs [SI]
  double expected_sd = 0;     ///< √(N.6) under the rest's model, RMS over the runs [SI]
  double statistic = 0;       ///< Σ z_r²
  double p_value = 1;
  bool stationary = true;
};

/// The first part of each run of at least 2 first_part_s against the rest of
/// that run, the channel y, the kept segments (masked samples are left out
/// of both means).
StationarityTest test_first_part(std::span<const double> y, double dt_s, std::span<const Segment> runs,
                                 std::span<const Segment> kept, const NoiseModel& rest_model, double first_part_s,
                                 double alpha);

/// The kept segments with the first `first_part_s` of each run removed.
std::vector<Segment> after_first_part(std::span<const Segment> runs, std::span<const Segment> kept, double dt_s,
                                      double first_part_s);

}  // namespace insmc::noise
