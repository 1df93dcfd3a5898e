#pragma once
/// Sampled noise of one sensor channel with the terms of a NoiseModel
/// (lib/noise/noise_terms.h), for a null that must carry a sensor's own
/// noise (the gap diagnosis's null through the import, docs/gap-method.md §2).
/// Each term by its own recursion at the sample interval dt, the sample
/// value being the channel's mean over [t_k, t_k + dt) (IMUs output
/// increments):
///   quantization Q   (θ_{k+1} − θ_k)/dt with θ_k ~ N(0, Q²)          σ² = 3Q²/τ²   (C.9)
///   white rate N     N/√dt · z_k                                      σ² = N²/τ     (C.12)
///   bias instab. B   a sum of first-order Gauss–Markov processes with
///                    T_c every half decade from kFlickerMinTimeS to
///                    kFlickerMaxTimeS, each of variance B² ln√10/π: their
///                    one-sided spectra add to B²/(π f) (the flicker
///                    spectrum whose σ² is (2 ln 2/π) B², (C.15)) between
///                    the extreme corner frequencies: its σ² lies within
///                    3 % of (C.15) for τ from 30 kFlickerMinTimeS to
///                    kFlickerMaxTimeS/10 and falls off outside
///   random walk K    b_{k+1} = b_k + K√dt · z_k, b_0 = 0                  σ² = K²τ/3    (C.18)
///   rate ramp R      ±R t, the sign drawn once                        σ² = R²τ²/2   (C.20)
///   Gauss–Markov σ,T_c exact: the process b at the sample times by its AR(1)
///                    b_{k+1} = φ b_k + σ√(1−φ²) z, φ = e^{−dt/T_c}, started
///                    from its stationary law, and the sample its exact mean
///                    over [t_k, t_k + dt] drawn jointly with b_{k+1}, so any
///                    T_c, even far below dt, has its own σ²(τ)        (C.23)
/// Slow Gauss–Markov processes (T_c ≥ 50 dt) are stepped every
/// ⌊T_c/(20 dt)⌋ samples with the exact φ of that step and held between
/// (their point values):
/// a hold of T_c/20 changes their Allan variance only below τ ≈ T_c/20,
/// where they are far under their level, and it saves most of the draws.
#include <cstddef>
#include <vector>

#include "lib/noise/noise_fit.h"
#include "lib/truth/noise.h"

namespace insmc::noise {

/// The band of the bias-instability approximation [s]: from below the
/// shortest filter windows to beyond the longest run a record holds (48 h).
inline constexpr double kFlickerMinTimeS = 0.1;
inline constexpr double kFlickerMaxTimeS = 3.2e5;

class NoiseSynthesizer {
 public:
  /// `first_stream`: the NormalSource streams used are first_stream, +1, …,
  /// + streams_used() − 1.
  NoiseSynthesizer(const NoiseModel& model, double dt_s, const NormalSource& normals, std::uint64_t first_stream);
  /// The next sample's noise (SI).
  double next();
  static constexpr std::uint64_t streams_used() { return 32; }

 private:
  struct Process {
    double phi = 0, next_sd = 0, value = 0;  ///< b_{next} = φ b + next_sd·z₁
    /// Stepped every sample: the sample is the mean of b over it,
    /// mean_gain·b + mean_common·z₁ + mean_own·z₂.
    double mean_gain = 0, mean_common = 0, mean_own = 0;
    long stride = 1, countdown = 0;
    NormalDraws draws;
  };
  void add_process(double sigma, double correlation_time_s, const NormalSource& normals, std::uint64_t stream);

  double dt_s_;
  double white_scale_ = 0, quantization_ = 0, walk_step_ = 0, ramp_slope_ = 0;
  double angle_ = 0, walk_ = 0;
  long k_ = 0;
  NormalDraws white_, quantization_draws_, walk_draws_;
  std::vector<Process> processes_;
};

}  // namespace insmc::noise
