#pragma once
/// The standard noise terms of an inertial sensor channel (IEEE Std 952-1997
/// Annex C, Table C.1; IEEE Std 1554-2005 Table 3) and a first-order
/// Gauss–Markov process, each with
/// - its Allan variance per unit of its power p (p = coefficient²), which is
///   linear in p so a fit of several terms is a non-negative least squares;
/// - its generalized structure function D(s) = E[(θ(t+s) − θ(t))²] of the
///   integrated output θ, defined up to terms of degree ≤ 2 in s that cancel
///   in every second difference, from which the variance of the difference of
///   two averages (the stationarity test) follows:
///   Var(ȳ_B − ȳ_A) = [2D(τ) − D(s+τ) − D(|s−τ|) + 2D(s)] / τ²            (N.1)
///   for two averages over τ whose starts are s ≥ τ apart. At s = τ this is
///   2σ²(τ), the Allan variance's own definition.
/// Names and units (gyro / accelerometer, SI):
///   quantization Q           rad   / m/s        σ² = 3Q²/τ²             (C.9)
///   white rate (ARW / VRW) N rad/√s / m/s/√s    σ² = N²/τ               (C.12)
///   bias instability B       rad/s / m/s²       σ² = (2 ln 2/π) B²      (C.15), flat part
///   rate random walk K       rad/s/√s / m/s²/√s σ² = K²τ/3              (C.18)
///   rate ramp R              rad/s² / m/s³      σ² = R²τ²/2             (C.20)
///   Gauss–Markov σ, T_c      rad/s / m/s², s    σ² = σ²T_c/τ² [2τ − T_c(3 − 4e^{−τ/T_c} + e^{−2τ/T_c})]
///                                                                        (C.23 with q_c = 2σ²/T_c)
#include <array>
#include <string_view>

namespace insmc::noise {

enum class NoiseTerm { kQuantization, kWhiteRate, kBiasInstability, kRateRandomWalk, kRateRamp, kGaussMarkov };
inline constexpr std::array<NoiseTerm, 6> kAllNoiseTerms = {
    NoiseTerm::kQuantization,   NoiseTerm::kWhiteRate, NoiseTerm::kBiasInstability,
    NoiseTerm::kRateRandomWalk, NoiseTerm::kRateRamp,  NoiseTerm::kGaussMarkov};

/// Which sensor a channel belongs to (names and units differ).
enum class SensorKind { kGyro, kAccelerometer };

/// "quantization", "angle_random_walk"/"velocity_random_walk",
/// "bias_instability", "rate_random_walk", "rate_ramp", "gauss_markov".
std::string_view term_name(NoiseTerm t, SensorKind s);
/// The SI unit of the term's coefficient, e.g. "rad/sqrt(s)".
std::string_view term_si_unit(NoiseTerm t, SensorKind s);

/// σ²(τ) per unit power p for the term (T_c used by the Gauss–Markov term only).
double avar_shape(NoiseTerm t, double tau_s, double correlation_time_s);
/// D(s) per unit power (generalized structure function, see above).
double structure_shape(NoiseTerm t, double lag_s, double correlation_time_s);
/// (N.1) per unit power: Var(ȳ_B − ȳ_A) for averages over tau_s, starts lag_s ≥ tau_s apart.
double mean_difference_shape(NoiseTerm t, double tau_s, double lag_s, double correlation_time_s);

/// The power-law type a term behaves as at τ (chooses the equivalent degrees
/// of freedom of the Allan variance there): Q white phase, N white rate, B
/// flicker rate, K and R random-walk rate, Gauss–Markov random walk below
/// T_c and white rate above.
int power_law_alpha(NoiseTerm t, double tau_s, double correlation_time_s);

}  // namespace insmc::noise
