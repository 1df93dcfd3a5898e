#pragma once
/// The overlapping Allan variance of one sensor channel (IEEE Std 952-1997
/// Annex C, IEEE Std 1554-2005 §6): for a rate series y_k sampled every τ0
/// and its integral θ_k = τ0 Σ_{i<k} y_i, at cluster time τ = m τ0
///
///   σ²(τ) = Σ_k (θ_{k+2m} − 2θ_{k+m} + θ_k)² / (2 τ² (N − 2m))          (C.4)
///
/// summed over every window of 2m samples that lies inside one segment (a
/// run, or the stretch between two masked disturbances), so that no window
/// spans a gap. Cluster sizes are octave spaced (m = 1, 2, 4, ...) up to a
/// third of the longest segment. Confidence intervals are chi-square with
/// the equivalent degrees of freedom of the noise type that dominates at τ
/// (docs/noise.md §2).
#include <cstddef>
#include <span>
#include <vector>

namespace insmc::noise {

/// A stretch of consecutive, equally spaced samples [begin, end).
struct Segment {
  std::size_t begin = 0, end = 0;
  std::size_t size() const { return end - begin; }
};

/// The power-law noise types of the frequency-stability literature, named
/// by the slope α of the rate's power spectral density S_y(f) ∝ f^α.
enum class PowerLaw { kWhitePhase = 2, kFlickerPhase = 1, kWhiteRate = 0, kFlickerRate = -1, kRandomWalkRate = -2 };

/// One cluster time of the overlapping Allan variance.
struct AllanLevel {
  double tau_s = 0;            ///< cluster time m τ0 [s]
  std::size_t cluster = 0;     ///< m [samples]
  double avar = 0;             ///< σ²(τ) [unit²]
  std::size_t windows = 0;     ///< second differences summed (Σ over segments of N_s − 2m)
  std::vector<std::size_t> segment_samples;  ///< N_s of each segment that holds a window
};

/// One level as the report gives it: the deviation, its interval, the
/// degrees of freedom under the fitted model, and the model's deviation
/// (0 where the model was not fitted).
struct AllanRow {
  double tau_s = 0, adev = 0, lower = 0, upper = 0, edf = 0, model_adev = 0;
  std::size_t windows = 0;
};

/// Overlapping Allan variance of y (one value per sample, spacing dt_s) over
/// the given segments, at m = 1, 2, 4, ... while 3m ≤ the longest segment
/// (and m ≤ max_cluster). Segments shorter than 3 samples are skipped.
std::vector<AllanLevel> overlapping_allan(std::span<const double> y, double dt_s, std::span<const Segment> segments,
                                          std::size_t max_cluster = static_cast<std::size_t>(-1));

/// Equivalent degrees of freedom of the overlapping Allan variance for N
/// phase points (N − 1 rate samples) at cluster m and the noise type
/// (NIST SP 1065, "Handbook of frequency stability analysis", Table 12,
/// after Howe, Allan and Barnes 1981). Over several segments the degrees of
/// freedom add (independent segments). At least 1.
double allan_edf(std::size_t phase_points, std::size_t m, PowerLaw type);
double allan_edf(const AllanLevel& level, PowerLaw type);

/// The two-sided chi-square interval [lo, hi] of an Allan *deviation* at
/// confidence `confidence`: σ √(edf / χ²_{(1±c)/2}(edf)).
struct DeviationInterval {
  double lo = 0, hi = 0;
};
DeviationInterval adev_interval(double avar, double edf, double confidence);

}  // namespace insmc::noise
