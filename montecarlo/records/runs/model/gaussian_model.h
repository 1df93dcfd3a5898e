#pragma once
/// The model of one run's observations as the diagnosis sees it: linear in
/// its causes with known second moments (the linear level, docs/gap-method.md),
///   y = μ + H c + e,  c ~ (0, diag(prior_var)),  e ~ (0, diag(noise_var)),
/// c = (x, effect coefficients): the first 33 columns are the uncertainties of
/// Table 3.1 (priors overridable), further columns come from candidate
/// effects (candidates.h). Only second moments are used, so nothing assumes
/// the uniform bounds of Table 3.1 are Gaussian.
#include <Eigen/Core>
#include <vector>

#include <optional>
#include <span>

#include "lib/uncertainty/uncertainty_vector.h"
#include "montecarlo/records/runs/model/pulse_counting.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::runs {

struct GaussianModel {
  Eigen::VectorXd mean;       ///< rows: E y (deterministic effects, same in every run)
  Eigen::MatrixXd H;          ///< rows × columns
  Eigen::VectorXd prior_var;  ///< columns
  /// rows, > 0: the noise the fit weights the rows by (with the model-error
  /// floor, so that the fit does not lean on sub-metre position detail the
  /// linear level does not promise).
  Eigen::VectorXd noise_var;
  /// rows, ≥ 0: the noise the data really carry (pulse counting, position
  /// resolution, a candidate's own noise; no floor). The expected squares the
  /// gap compares with come from this one (run_analysis.h); what the null
  /// shows beyond it is calibrated per group (gap_metric.h).
  Eigen::VectorXd actual_noise_var;
};

/// Share of the predicted position error the model-error floor allows for:
/// the truth's first-order terms the linear level takes with g instead of the
/// site's g_s (0.17 % at 45°) and its second-order terms (docs/truth-vs-models.md).
inline constexpr double kRelativeModelError = 0.003;
/// Absolute model-error floor of r rows [m] (docs/truth-vs-models.md: truth and linear agree
/// within 1 % + 1 m).
inline constexpr double kAbsoluteModelErrorM = 1.0;
/// Floor of the f noise [m/s²] (≈ 0.1 µg) so that a continuous output
/// (dv_pulse 0) still has a finite weight.
inline constexpr double kFNoiseFloorMps2 = 1e-6;

/// The base model of a layout: x with `x_var`, the counting of the record's
/// ΔV pulses (pulse_counting.h: f counting noise, the pulse phase and the
/// slow-axis sawtooth in r), r noise of the position resolution q²/12 and the
/// model-error floor.
struct BaseModel {
  Eigen::MatrixXd H_x;             ///< rows × 33
  UncertaintyVector x_var;
  Eigen::VectorXd noise_var;       ///< rows: fit weights (resolution and the model-error floor)
  Eigen::VectorXd actual_noise_var;  ///< rows: the position resolution alone
  Eigen::VectorXd prior_std;       ///< rows: predicted std of each row from x alone
  PulseCounting counting;          ///< of the record's pulse weight
  /// After a scheme (scheme_rows.h): further causes (prior: the combined
  /// x variance of slot scheme_x_index, or scheme_variance where −1) and
  /// what the test-run estimates add to each row (taken off the data).
  Eigen::MatrixXd scheme_columns;
  std::vector<int> scheme_x_index;
  Eigen::VectorXd scheme_variance;
  Eigen::MatrixXd estimate_map;
};
BaseModel make_base_model(const Layout& layout, const RecordSite& site, const UncertaintyVector& x_var);

/// A candidate effect's addition to the base model.
struct Extension {
  Eigen::MatrixXd columns;          ///< rows × m (may be 0 columns)
  Eigen::VectorXd column_var;       ///< m
  UncertaintyVector x_var_scale = UncertaintyVector::Ones();  ///< multiplies x_var
  UncertaintyVector x_var_add = UncertaintyVector::Zero();    ///< then added
  /// rows, or empty: noise the effect adds to the data (added to the fit
  /// weights and to the actual noise alike).
  Eigen::VectorXd noise_var_add;
  /// rows, or empty: a deterministic signature, the same in every run (a
  /// design or site effect), subtracted from the data before the fit.
  Eigen::VectorXd mean;
  /// Pulse counting that replaces the base model's (pulses of another weight).
  std::optional<PulseCounting> counting;
  /// True when `columns` and `mean` are only the higher-order terms of an
  /// effect that acts through the priors (x_var_scale, x_var_add) to first
  /// order: e.g. a large misalignment's rotation to second order. Whatever
  /// reads the effect to first order (the test run's estimates, linear in
  /// the causes) may take the priors alone.
  bool columns_higher_order = false;

  /// True when the extension only moves the mean (the covariance, hence the
  /// fit, is the one without it).
  bool mean_only() const {
    return columns.cols() == 0 && noise_var_add.size() == 0 && (x_var_scale.array() == 1.0).all() &&
           (x_var_add.array() == 0.0).all() && !counting;
  }
};

/// The base model or an extension of a layout's union (layout_union.h) on
/// the rows `rows` of it: each row's model is its own, so the result is the
/// model of the layout those rows make.
BaseModel select_rows(const BaseModel& base, std::span<const Eigen::Index> rows);
Extension select_rows(const Extension& extension, std::span<const Eigen::Index> rows);
GaussianModel select_rows(const GaussianModel& model, std::span<const Eigen::Index> rows);

/// The base model with every extension applied.
GaussianModel combine(const BaseModel& base, const std::vector<const Extension*>& extensions);

/// The model of the first `rows` rows alone (the marginal of a run that
/// stopped early: the same causes, the rows it has).
GaussianModel first_rows(GaussianModel model, Eigen::Index rows);

}  // namespace insmc::runs
