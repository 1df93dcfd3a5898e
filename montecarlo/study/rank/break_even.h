#pragma once
/// The assumptions that decide which compensation scheme comes first, and
/// the values at which the first place changes, on the covariance level
/// (study_map.h: the exact RMS of the paper or linear model, no sampling
/// noise, so a crossing is a property of the model, not of a draw).
///
/// How each is found, exactly rather than by a tolerance:
///   * a scheme's measurement error set to uniform ±b per axis
///     (alignment_drift_error = ω_ie E4 of (5.15), reset_velocity_error,
///     reset_position_error of (5.8), the realignment's re-sighting
///     realignment_azimuth_error): every output's mean square is
///     A + C b² (a variance b²/3 through a fixed map), so two evaluations give
///     A and C and a crossing solves a linear equation in b²;
///   * the random fraction F (lib/uncertainty/random_fraction.h): the
///     bounds are (1 − F)·B and F·B, so the mean square is quadratic in F;
///     three evaluations give it and a crossing is a root in [0, 1];
///   * the test duration T: no closed form (the estimators change with T);
///     a scan over whole minutes, then bisection on whole filter intervals.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

enum class Assumption {
  kAlignDriftError,
  kResetVelocityError,
  kResetPositionError,
  kRealignAzimuthError,
  kRandomFraction,
  kTestDuration
};
inline constexpr Assumption kAllAssumptions[] = {Assumption::kAlignDriftError,     Assumption::kResetVelocityError,
                                                 Assumption::kResetPositionError,  Assumption::kRealignAzimuthError,
                                                 Assumption::kRandomFraction,      Assumption::kTestDuration};

/// The name in breakeven.csv (a catalogue group, `random_fraction` or
/// `test_duration`) and its SI unit.
std::string_view to_string(Assumption a);
std::string_view si_unit(Assumption a);

/// The first catalogue slot of an assumption that is a bound (its x, y, z,
/// or its one slot), or -1 (the random fraction, the test duration); and
/// how many slots it bounds.
int bound_slot(Assumption a);
/// False for a bound that acts in the other system only (the theodolite's
/// realignment_azimuth_error in system 2).
bool applies_to(Assumption a, System system);

/// The study with the assumption at `value` (SI): a bound of a uniform
/// ±value on each axis, the random fraction, or the test duration.
StudyConfig with_assumption(const StudyConfig& config, Assumption a, double value);

/// The assumption's value in the study (SI); NaN when it is not one value
/// (a bound whose axes differ or are not uniform, a random fraction the
/// --bound options overrode).
double study_value(const StudyConfig& config, Assumption a);

/// Horizontal RMS [m] on the covariance level at the report times:
/// rms[system j][report time k][scheme i] (config order).
using RmsTable = std::vector<std::vector<std::vector<double>>>;
RmsTable predicted_horizontal_rms(const StudyConfig& config);

/// Index of the smallest RMS (the first place) among one RmsTable entry's schemes.
std::size_t leader_of(const std::vector<double>& rms);

/// The scheme first at the study's own settings and a challenger that ties
/// with it at `value_si` of the assumption.
struct Crossing {
  System system;
  double t_s;
  Assumption assumption;
  Scheme leader, challenger;
  double value_si;
};

/// Each scheme's RMS along an assumption's range, for the plot: rms[v] at
/// values_si[v] (from the same polynomials or scan as the crossings).
struct AssumptionCurve {
  Assumption assumption;
  std::vector<double> values_si;
  std::vector<RmsTable> rms;
};

struct BreakEven {
  /// Every crossing of the leader (at the study's settings) with another
  /// scheme, per system and report time: bounds within their catalogue range
  /// (bound_range), F in [0, 1], T on
  /// whole filter intervals within [max(4τ, 1 min), max_test_duration_s].
  /// Sorted by system, time, assumption, value.
  std::vector<Crossing> crossings;
  std::vector<AssumptionCurve> curves;  ///< kAllAssumptions order
  RmsTable at_study;                    ///< the RMS at the study's own settings
};

/// Told the stage, the study maps built in it so far and how many it has in
/// all (from several threads at once: the callee serialises).
using BreakEvenProgress = std::function<void(std::string_view stage, std::uint64_t done, std::uint64_t total)>;

BreakEven break_even(const StudyConfig& config, double max_test_duration_s = 40 * 60.0,
                     const BreakEvenProgress& progress = {});

}  // namespace insmc::mc
