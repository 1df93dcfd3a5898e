#pragma once
/// The study as linear maps: per alignment system, every output row (x, y,
/// z, north, east per scheme × time) as a row acting on the extended vector
/// z of that system's pipeline (lib/compensation/extended_vector.h), so a
/// block of samples is one matrix product per system. Also the exact
/// linear-covariance prediction of every output (mean, RMS, Var(r²)) from
/// z = G w (system_pipeline.h), and the error budget.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "montecarlo/study/model/system_pipeline.h"
#include "montecarlo/study/model/output_layout.h"

namespace insmc::mc {

inline constexpr int kRowsPerMap = 5;  // x, y, z, north, east

/// The exact first and second moments of a horizontal output's (north,
/// east) error: its mean and 2×2 covariance.
struct HorizontalMoments {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
};

class StudyMap {
 public:
  StudyMap(const StudyConfig& config, const StudyLayout& layout);

  const SystemPipeline& pipeline(int system_j) const { return *pipelines_[system_j]; }
  const StudyLayout& layout() const { return *layout_; }
  const StudyConfig& config() const { return *config_; }
  /// z_slot::kDim × rows of system j; column 5·(scheme_i · n_times + k) + c.
  const Eigen::MatrixXd& transposed(int system_j) const { return map_t_[system_j]; }
  /// First row (in transposed(j)) of output o's five rows, and its system.
  int row_base(std::size_t output) const;
  /// True when system j's outputs depend on x alone (e.g. scheme none): the
  /// engine then skips the test-run pipeline and multiplies x directly.
  bool depends_on_x_only(int system_j) const { return x_only_[system_j]; }
  int system_index(std::size_t output) const;

  /// Output value from its five row values (sqrt(N² + E²) for horizontal).
  static double output_value(const double* five_rows, Axis axis);

  /// Exact predictions per output (layout order): E[r], sqrt(E[r²]), Var(r²).
  const std::vector<double>& predicted_mean() const { return mean_; }
  const std::vector<double>& predicted_rms() const { return rms_; }
  const std::vector<double>& predicted_var_r2() const { return var_r2_; }
  /// Of a horizontal output (zero for the others).
  const HorizontalMoments& predicted_horizontal(std::size_t output) const { return horizontal_[output]; }

  /// Error budget per output: named sources and their shares of E[r²]
  /// (catalogue parameters, realignment draws, measurement noises, and
  /// `mean` for the squared mean); shares sum to 1 where E[r²] > 0.
  std::vector<std::string> budget_sources() const;
  std::vector<std::vector<double>> budget_shares() const;

  /// Per scheme (config order): time from the first switch-over to flight.
  double ready_time_s(int scheme_i) const { return ready_time_s_[scheme_i]; }
  const std::string& fitted_terms(int system_j) const { return pipelines_[system_j]->estimators().fitted_terms; }

 private:
  const StudyConfig* config_;
  const StudyLayout* layout_;
  std::vector<std::shared_ptr<const SystemPipeline>> pipelines_;
  std::vector<Eigen::MatrixXd> map_t_;
  std::vector<bool> x_only_;
  std::vector<Eigen::MatrixXd> input_map_t_;  // W × rows: (G^T M^T) per system
  std::vector<double> mean_, rms_, var_r2_, ready_time_s_;
  std::vector<HorizontalMoments> horizontal_;
};

}  // namespace insmc::mc
