#pragma once
/// The study as one linear map: every output row (x, y, z, north, east per
/// scheme × system × time) as a row of a matrix acting on the uncertainty
/// vector, so a block of samples is one matrix product. Also the exact
/// linear-covariance prediction of every output (mean, RMS, Var(r²)).
#include <Eigen/Core>
#include <vector>

#include "montecarlo/study/output_layout.h"

namespace insmc::mc {

class StudyMap {
 public:
  StudyMap(const StudyConfig& config, const StudyLayout& layout);

  /// Transposed map, kDim × rows: column 5·m + c is row c ∈ {x, y, z, N, E}
  /// of map m = (scheme, system, time) in layout order.
  const Eigen::MatrixXd& transposed() const { return map_t_; }
  int rows() const { return static_cast<int>(map_t_.cols()); }

  /// Output value for one sample from its row values (5 per map).
  static double output_value(const double* five_rows, Axis axis);

  /// Exact predictions per output (layout order) under the study's
  /// uncertainty model: E[r], sqrt(E[r²]) and Var(r²) (for statistical tests).
  const std::vector<double>& predicted_mean() const { return mean_; }
  const std::vector<double>& predicted_rms() const { return rms_; }
  const std::vector<double>& predicted_var_r2() const { return var_r2_; }

  /// Per output, each uncertainty's share of E[r²] (zero-mean part), and the
  /// share of the squared mean; they sum to 1 where E[r²] > 0.
  std::vector<std::vector<double>> variance_shares() const;
  std::vector<double> mean_shares() const;

 private:
  const StudyConfig* config_;
  const StudyLayout* layout_;
  Eigen::MatrixXd map_t_;
  std::vector<double> mean_, rms_, var_r2_;
};

}  // namespace insmc::mc
