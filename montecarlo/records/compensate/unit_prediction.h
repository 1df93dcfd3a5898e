#pragma once
/// One unit's test run turned into what its crew needs (docs/compensate.md):
/// the report's coefficients U2..U4 (3.29b–d) of this unit with their
/// uncertainty, the compensation each scheme would apply from its
/// estimates, and the position error after each scheme, this unit's and the
/// population's.
///
/// The run model is the gap diagnosis' (runs/model/gaussian_model.h: linear
/// level, pulse counting, position resolution, the schemes' maps of
/// scheme_rows.h): test rows y = H_t c + e and the position error after a
/// scheme p = A c + E û, c the causes (x of Table 3.1, counting, a
/// realignment's fresh draws), û = B y the report's estimates, applied to
/// this unit's data. Conditioning on y is linear (the best linear estimate of
/// c from y, with the priors' second moments; no Gaussian prior is assumed
/// for the mean and covariance below):
///   ĉ = μ + G (y − H_t μ),  G = P H_tᵀ (H_t P H_tᵀ + W)⁻¹,
///   error covariance (I − G H_t) P (I − G H_t)ᵀ + G W Gᵀ,
/// W the rows' noise with the model-error floor (the linear level's
/// allowance against the truth). This unit: p has mean A ĉ + E û and
/// covariance A (error) Aᵀ
/// plus the counting noise of the navigation rows. The population: û
/// random too, p = (A + E B H_t) c + E B e, unconditioned.
#include <optional>
#include <string>
#include <vector>

#include "lib/compensation/scheme.h"
#include "lib/frames/frames.h"
#include "montecarlo/records/compensate/unit_records.h"
#include "montecarlo/records/runs/model/gaussian_model.h"

namespace insmc::compensate {

/// The chi-square of a unit's test rows against S = H P Hᵀ + W (W with the
/// model-error floor) for rows of covariance S_a = H P Hᵀ + W_a (the actual
/// noise, no model error): a quadratic form of mean tr(S⁻¹S_a) and, for
/// Gaussian rows, variance 2 tr((S⁻¹S_a)²). Table 3.1's uniform draws have
/// less kurtosis than a Gaussian's, so the spread is an upper bound.
struct ConsistencyBand {
  double linear_mean = 0.0, linear_sd = 0.0;
  /// The upper-tail probability of `chi2` for rows of the linear level
  /// alone: Satterthwaite's c·χ²(ν) of the same mean and variance (the
  /// quadratic form is a weighted sum of χ²(1), weights the eigenvalues of
  /// S⁻¹S_a, all in (0, 1]); 1 when the band is empty.
  double linear_p(double chi2) const;
};

/// The band of a model's test rows: S its rows' covariance with the floor
/// (H P Hᵀ + noise_var), the actual noise actual_noise_var.
ConsistencyBand consistency_band(const runs::GaussianModel& model, const Eigen::LLT<Eigen::MatrixXd>& S);

/// One coefficient of the report for this unit.
struct UnitEstimate {
  std::string name;        ///< "U2_x", ..., "df_T_z"
  std::string unit;        ///< SI unit ("rad" for U2..U4: angles, (3.29b-d))
  double value = 0.0;      ///< this unit's best linear estimate (conditioned mean)
  double sigma = 0.0;      ///< its error's standard deviation
  double prior_sigma = 0.0;  ///< the population's spread before the test run
  /// The report's estimator of the same quantity ((4.8b), (4.8c), (5.10)):
  /// what the schemes apply; absent for U4, which no scheme applies.
  std::optional<double> report_estimator;
  /// The test run determines it: its sigma is below half its prior spread.
  bool resolved() const { return sigma < 0.5 * prior_sigma; }
};

/// What a scheme sets from this unit's estimates (its truth_action,
/// lib/compensation/schemes/), in SI.
struct SchemeCompensation {
  Vec3 step_mps2 = Vec3::Zero();      ///< at point 2
  Vec3 ramp_mps3 = Vec3::Zero();      ///< through integrators into point 2
  Vec3 torquer_radps = Vec3::Zero();  ///< at point 4
  bool resets_at_test_end = false;    ///< velocity and position reset at T (points 5, 6)
  bool realigns = false;
  /// 5.4: from the alignment phase's torquer commands and accelerometer
  /// outputs, which the records do not hold (modelled as their maps of x).
  bool from_alignment_data = false;
};

/// The position error at one time on the scheme's clock, in a′ [m].
struct UnitPositionError {
  double t_s = 0.0;
  Vec3 mean_m = Vec3::Zero();        ///< this unit's
  Mat3 covariance_m2 = Mat3::Zero(); ///< this unit's
  Mat3 population_m2 = Mat3::Zero(); ///< second moment over the population
  /// a′ → local-level horizontal (north, east) at this time (position_maps.h).
  Eigen::Matrix<double, 2, 3> horizontal = Eigen::Matrix<double, 2, 3>::Zero();

  double unit_rms_m(int axis) const;
  double population_rms_m(int axis) const;
  double unit_horizontal_rms_m() const;
  double population_horizontal_rms_m() const;
  Eigen::Vector2d horizontal_mean_m() const { return horizontal * mean_m; }
  Eigen::Matrix2d horizontal_covariance_m2() const { return horizontal * covariance_m2 * horizontal.transpose(); }
};

struct SchemePrediction {
  Scheme scheme;
  double ready_time_s = 0.0;
  SchemeCompensation compensation;
  std::vector<UnitPositionError> envelope;  ///< at the requested clock times
};

/// The run model of one unit's test rows (uncompensated: the test run is
/// recorded before any scheme acts) conditioned on its data. Its causes are
/// x and the test rows' pulse counting.
struct UnitPosterior {
  runs::GaussianModel model;          ///< of the test rows
  Eigen::VectorXd cause_mean;        ///< μ, the prior mean of the causes
  Eigen::VectorXd cause_estimate;    ///< ĉ
  Eigen::MatrixXd error_covariance;  ///< of ĉ − c
  /// Whether the test rows fit the model at all: y − Hμ against its
  /// covariance S, (y − Hμ)ᵀ S⁻¹ (y − Hμ) ~ χ²(rows) for data of the model
  /// (less with the model-error floor in S); p its upper-tail probability.
  double consistency_chi2 = 0.0;
  int consistency_dof = 0;
  double consistency_p = 1.0;
  /// Where rows of the linear level itself (no model error, only the rows'
  /// actual noise) put that chi-square: its mean and standard deviation.
  /// The floor is an allowance, so data of the model lie between this and
  /// χ²(rows); p above is taken against the full allowance.
  ConsistencyBand consistency_band;
  Eigen::MatrixXd estimates_map;     ///< B: the report's estimates per unit of the test rows
  /// What the crew's estimators give: from Δr = r − r(0) (4.7), r(0) the
  /// position read at switch-over. Records hold no row at t = 0, so r(0) is
  /// this unit's estimated initial position error (3.22); the estimates from
  /// r itself (UnitTestRun::estimates) differ by the estimators' response
  /// to r(0), which the model carries exactly (scheme_rows.h).
  TestRunEstimates crew_estimates;
};
UnitPosterior condition_unit(const UnitRecords& records, const UnitTestRun& run, const UncertaintyModel& prior);

/// What conditioning needs that is the same for every unit of one test-run
/// layout (all the units of a file, as a rule): the model of the test rows,
/// its gain and the estimators' map, built once and used for each unit.
struct UnitConditioning {
  runs::Layout layout;
  runs::GaussianModel model;
  Eigen::VectorXd cause_mean;
  Eigen::MatrixXd estimates_map;
  Eigen::MatrixXd gain;              ///< G = P Hᵀ S⁻¹
  Eigen::MatrixXd error_covariance;  ///< of the linear estimate
  Eigen::LLT<Eigen::MatrixXd> row_covariance;  ///< S = H P Hᵀ + W
  ConsistencyBand consistency_band;
};
UnitConditioning unit_conditioning(const UnitRecords& records, const runs::Layout& layout, const UncertaintyModel& prior);
/// condition_unit with the shared part built before (run.layout == shared.layout).
UnitPosterior condition_unit(const UnitRecords& records, const UnitTestRun& run, const UnitConditioning& shared);

/// What a coefficient of the report mixes and how far a test run separates
/// it: the uncertainties of Table 3.1 that make up its spread (their share
/// of its prior variance, the largest three of at least 1 %), and its sigma
/// after test runs of T, 2T and 4T of as many filter windows (no data
/// needed: the error covariance of the linear estimate).
struct Identifiability {
  std::string name;
  std::vector<std::pair<std::string, double>> mixes;
  double prior_sigma = 0.0;
  std::vector<std::pair<double, double>> sigma_by_duration;  ///< (T' [s], sigma)
};
std::vector<Identifiability> identifiability(const UnitRecords& records, const UncertaintyModel& prior);

/// U2, U3, U4 (3.29b–d) and the accelerometer output error at T of (5.10),
/// per axis, for one unit.
std::vector<UnitEstimate> estimate_unit(const UnitRecords& records, const UnitPosterior& posterior,
                                        const UncertaintyModel& prior);

/// The scheme's compensation and position error at `clock_s` (> 0, on the
/// scheme's clock: clock_of) for one unit and its population. The
/// navigation after the scheme is a model of its own (scheme_rows.h) sharing
/// x with the test run; its further causes (a realignment's fresh draws,
/// r(0)'s rounding, 5.4's counting, the navigation's own pulse counting)
/// are taken independent of the test rows.
SchemePrediction predict_scheme(const UnitRecords& records, const UnitTestRun& run, const UnitPosterior& posterior,
                                Scheme scheme, const UncertaintyModel& prior, const std::vector<double>& clock_s,
                                double realignment_duration_s);

/// What predict_scheme needs that is the same for every unit of one test-run
/// layout: the scheme's navigation model, the covariances (the error of a
/// linear estimate does not depend on the data) and the population's, built
/// once from any unit's posterior of that layout.
struct SchemeModel {
  Scheme scheme;
  std::vector<double> clock_s;
  double realignment_duration_s = 0.0;
  Eigen::MatrixXd position_per_cause;     ///< the navigation rows per unit of x
  Eigen::VectorXd position_of_others;     ///< their mean from the other causes
  Eigen::MatrixXd position_per_estimate;  ///< per unit of the crew's estimates
  std::vector<UnitPositionError> envelope;  ///< every field but the unit's mean
};
SchemeModel scheme_model(const UnitRecords& records, const UnitPosterior& posterior, Scheme scheme,
                         const UncertaintyModel& prior, const std::vector<double>& clock_s,
                         double realignment_duration_s);
/// predict_scheme with the shared part built before.
SchemePrediction predict_scheme(const UnitRecords& records, const UnitTestRun& run, const UnitPosterior& posterior,
                                const SchemeModel& model);

}  // namespace insmc::compensate
