#pragma once
/// The preflight test run on a stationary base (chapter 4): its settings,
/// the observation maps of the chosen fidelity (the accelerometer output
/// error integrated over each filter interval, fig. 5.2, and the position
/// error change Δr^{a'}), and the least-squares estimators of (4.7)/(4.8)
/// and (4.4) as precomputed linear maps.
#include <optional>
#include <string>
#include <vector>

#include "lib/alignment/alignment_loops.h"
#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/frames/frames.h"
#include "lib/uncertainty/row_map.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "lib/units/physical_range.h"
#include "lib/units/units.h"

namespace insmc {

/// Vehicle sway (parked aircraft in wind): the velocity wiggle v_s(t) is a
/// first-order Gauss–Markov process per axis (stationary RMS
/// `velocity_rms_mps`, correlation time `correlation_time_s`); the
/// accelerometers sense its derivative (u)r̈, which the filter box averages
/// to (v_s(t_k) − v_s(t_{k−1}))/τ. The navigation position is not affected
/// (the motion is real); the velocity resets of 5.2/5.3 see v_s(T).
struct SwayOptions {
  double velocity_rms_mps = 0.0;     ///< 0 = off (default)
  double correlation_time_s = 6.0;   ///< > 0
  bool enabled() const { return velocity_rms_mps > 0; }
};

/// Which coefficient of (4.4)/(4.7) the estimators fit.
enum class FitU4 { kAuto, kYes, kNo };

struct TestRunOptions {
  double duration_s = 900.0;                 ///< T, the test run (15 min)
  double filter_interval_s = 10.0;           ///< τ of the filter box (fig. 5.2); T must be a multiple
  double dv_pulse_mps = 0.1 * kFtpsToMps;    ///< ΔV pulse weight (§4.3); 0 = continuous output
  double position_resolution_m = 3 * kFtToM; ///< position computer resolution ("a few feet"); 0 = exact
  FitU4 fit_u4 = FitU4::kAuto;               ///< U4: fit when resolvable (auto), demand it, or never
  SwayOptions sway;
  /// Scheme 5.4: the torquer commands and accelerometer outputs are averaged
  /// over the last `alignment_average_s` of the alignment; the torquer
  /// commands are counted in angle pulses of `torquer_pulse_rad` and the
  /// accelerometer outputs in ΔV pulses, each with its remainder carried.
  double alignment_average_s = 600.0;
  double torquer_pulse_rad = 1.0 * kArcsecToRad;
  /// Duration of the realignment of 5.1.1, 5.1.2 and combined (5-15 min practical, §5.1.2).
  double realignment_duration_s = 600.0;
  /// The truth level's fine alignment in the time domain (alignment_loops.h);
  /// nullopt = the loops' steady state. The linear-in-x levels have only the
  /// steady state.
  std::optional<AlignmentLoopSettings> alignment_loops;

  int intervals() const;  ///< K = ⌊T/τ⌋, the filter windows that end within T (T/τ in a study)
};

/// Physical ranges of the test-run settings (validate() and --help use them).
namespace test_run_range {
/// The report's test runs last minutes; two hours is the longest a crew would hold a vehicle.
inline constexpr PhysicalRange kDuration{0.0, 2 * 3600.0, true};
/// A filter box counts over seconds (fig. 5.2): from 0.1 s up to the run itself.
inline constexpr PhysicalRange kFilterInterval{0.1, 2 * 3600.0};
/// Pulse weights of real accelerometers lie between 1e-4 and 0.1 m/s; 1 m/s is coarser than any.
inline constexpr PhysicalRange kDvPulse{0.0, 1.0};
/// A position computer's least count: from exact (0) to a kilometre.
inline constexpr PhysicalRange kPositionResolution{0.0, 1000.0};
/// A realignment takes time: at least a second (a record file's navigation
/// starts after it, nav_start_s > T; a duration of 1e-300 s left them equal).
inline constexpr PhysicalRange kRealignmentDuration{1.0, 6 * 3600.0};
inline constexpr PhysicalRange kAlignmentAverage{0.0, 6 * 3600.0, true};
/// One torquer pulse: from exact (0) to 1 mrad (≈ 206 arcsec; real ones are about 1 arcsec).
inline constexpr PhysicalRange kTorquerPulse{0.0, 1e-3};
/// Sway of a parked vehicle: velocity wiggle up to 1 m/s RMS, correlation 0.1 s to 1 h.
inline constexpr PhysicalRange kSwayVelocity{0.0, 1.0};
inline constexpr PhysicalRange kSwayCorrelationTime{0.1, 3600.0};
}  // namespace test_run_range

/// Throws InputError naming the first field out of range.
void validate(const TestRunOptions& options);

/// Observation maps at t_k = kτ, k = 0..K, per unit of each uncertainty.
struct TestRunMaps {
  std::vector<double> t_s;
  std::vector<Sensitivity3> velocity_increment;  ///< ∫₀^{t_k} Δf^a dt [m/s], the pulse counters' signal
  std::vector<Sensitivity3> position_change;     ///< Δr^{a'}(t_k) = δr(t_k) − δr(0) [m]
};

/// Maps of the `paper` level ((4.4) integrated, (3.29) − δr(0)) or of the
/// `linear` level (the forcing of (3.24) integrated, the ODE solution).
TestRunMaps test_run_maps(System system, Fidelity fidelity, const ModelOptions& model,
                          const TestRunOptions& options);

/// The nominal velocity increment ∫₀^t f̂^{a'} dt of a stationary vehicle
/// (f̂^{a'} = −C_n^{a'}(t) g_e) [m/s]: what the pulse counters count besides
/// the errors, which sets the phase of their quantization.
Vec3 nominal_velocity_increment(double t_s, const ModelOptions& model);

/// The true position of the vehicle in a' [m] at t (for the position
/// computer's quantization phase).
Vec3 true_position_ap(double t_s, const ModelOptions& model);

/// The least-squares estimators (QR on column-scaled design matrices).
struct TestRunEstimators {
  bool fit_u3 = true, fit_u4 = false;
  /// Position data Δr_k, k = 1..K, per axis → (Û1, Û2, Û3, Û4) of (4.7):
  /// rows 0..3 (rows of unfitted terms are zero).
  Eigen::Matrix<double, 4, Eigen::Dynamic> position;
  /// Interval-averaged Δf_k, k = 1..K, per axis → (Â1, Û3, Û4) of (4.4).
  Eigen::Matrix<double, 3, Eigen::Dynamic> accel;
  /// "U1,U2,U3" etc.: what was fitted.
  std::string fitted_terms;
};

/// What the compensation schemes take from the test run, one row each per
/// column of the data (an axis, or a column of a linear map of the data).
enum EstimateRow { kU2Row, kU3Row, kU3AccelRow, kDfAtTestEndRow, kEstimateRows };

/// (5.10): the filtered Δf̂(T) = g(Â1 + Û3 ω_ie T + Û4 ω_ie² T²/2) from the
/// accelerometer fit's Â1, Û3, Û4 (the one statement of it: apply_estimators
/// and the Monte Carlo's block path both call it).
inline double filtered_df_at_test_end(const ModelOptions& m, double test_duration_s, double a1, double u3, double u4) {
  const double g = m.gravity_mps2, w = m.earth_rate_radps, T = test_duration_s;
  return g * ((a1 + w * T * u3) + w * w * T * T / 2 * u4);
}

/// The one application of the estimators: from K rows of position data Δr_k
/// and of interval-averaged accelerometer data Δf_k (any number of columns),
/// Û2, Û3 (4.8b, c), Û3 from the accelerometer data (the slope of (4.4),
/// (5.12)) and the filtered Δf̂(T) = g(Â1 + Û3 ω_ie T + Û4 ω_ie² T²/2) (5.10).
/// `Cols` fixed (3 axes) keeps the per-sample path free of allocations.
template <int Cols = Eigen::Dynamic, typename Position, typename Accel>
Eigen::Matrix<double, kEstimateRows, Cols> apply_estimators(const TestRunEstimators& est, const ModelOptions& m,
                                                            double test_duration_s, const Position& position,
                                                            const Accel& accel) {
  const Eigen::Matrix<double, 4, Cols> u_pos = est.position * position;  // (4.8): Û1..Û4
  const Eigen::Matrix<double, 3, Cols> u_acc = est.accel * accel;        // (4.4): Â1, Û3, Û4
  Eigen::Matrix<double, kEstimateRows, Cols> out(static_cast<Eigen::Index>(kEstimateRows), position.cols());
  out.row(kU2Row) = u_pos.row(1);
  out.row(kU3Row) = u_pos.row(2);
  out.row(kU3AccelRow) = u_acc.row(1);
  for (Eigen::Index c = 0; c < position.cols(); ++c)
    out(kDfAtTestEndRow, c) = filtered_df_at_test_end(m, test_duration_s, u_acc(0, c), u_acc(1, c), u_acc(2, c));
  return out;
}

/// The filter intervals k = 1..K whose data a run has, the position data
/// (r) and the accelerometer data (f) apart: records of a logger that
/// dropped samples. Empty: every interval.
struct ObservedIntervals {
  std::vector<bool> position, accel;
};

/// Builds the estimators. `u4_resolvable`/`u3_resolvable` follow
/// resolvable_terms(); with FitU4::kYes and U4 not resolvable this throws
/// InputError (the report's Table 4.3: e.g. U4 needs more than 15–20 min).
/// The fits (4.4), (4.8) are least squares over the K intervals; with
/// `observed` they are the same fits over the intervals a run has (a
/// missing interval's column of each estimator is zero).
TestRunEstimators make_estimators(const TestRunOptions& options, const ModelOptions& model,
                                  bool u3_resolvable, bool u4_resolvable, const ObservedIntervals& observed = {});

/// (4.6) applied to the study: a term is resolvable when its resolution
/// limit is below the prior RMS of its coefficient (largest axis), the prior
/// RMS from the printed U3/U4 maps and the uncertainty model. With
/// continuous outputs (ΔV = 0) every term is resolvable.
struct Resolvability {
  bool u3, u4;
  double u3_limit, u4_limit, u3_prior_rms, u4_prior_rms;
};
Resolvability resolvable_terms(System system, const ModelOptions& model, const TestRunOptions& options,
                               const UncertaintyModel& uncertainties);

}  // namespace insmc
