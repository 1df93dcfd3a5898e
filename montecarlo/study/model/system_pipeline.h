#pragma once
/// What one sample goes through for one alignment system:
/// the fresh per-alignment draws of a realignment, the preflight test run
/// (ΔV pulse counts through the filter box, the position computer at its
/// resolution, optional sway), the least-squares fits, and the
/// alignment-phase measurements of 5.4 — producing the extended vector z of
/// lib/compensation/extended_vector.h, from which every scheme's position
/// error is a linear map. Quantization is simulated (floor of the counted
/// signal with its carried remainder), never drawn from an assumed
/// distribution.
///
/// The same data path also gives z as an exact linear map G of independent
/// inputs w (x, the fresh draws, and the measurement noises modelled as
/// additive: uniform rounding of one pulse per count, dithered position
/// rounding, the Gauss–Markov sway) for the linear-covariance prediction.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "lib/compensation/extended_vector.h"
#include "lib/preflight/test_run.h"
#include "montecarlo/study/sampler/sampler.h"
#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

class SystemPipeline {
 public:
  SystemPipeline(const StudyConfig& config, System system);

  System system() const { return system_; }
  const TestRunEstimators& estimators() const { return est_; }

  /// Fills z (kDim × n, one column per sample) for samples first..first+n−1
  /// whose uncertainties are the columns of x (uncertainty_slot::kDim × n); for --replay
  /// and tests, through extended_vectors_by_draw (the same bits).
  void extended_vectors(std::uint64_t first, std::size_t n, const Eigen::MatrixXd& x, Eigen::MatrixXd& z) const;

  /// The engine's form: rows 0..n−1 of z (at least n rows, z_slot::kDim
  /// columns) for samples first..first+n−1, whose uncertainties are
  /// x_by_draw[j·n + s] (draw-major, as the block product takes them).
  void extended_vectors_by_draw(std::uint64_t first, std::size_t n, const double* x_by_draw,
                                Eigen::MatrixXd& z) const;

  /// z = G w + m for the additive-noise model: G (z_slot::kDim × W) and each
  /// input's mean, variance and fourth central moment.
  const Eigen::MatrixXd& covariance_map() const { return g_; }
  const Eigen::VectorXd& input_mean() const { return w_mean_; }
  const Eigen::VectorXd& input_variance() const { return w_var_; }
  const Eigen::VectorXd& input_fourth_moment() const { return w_m4_; }

 private:
  void build_covariance_map(const StudyConfig& c, const TestRunMaps& maps);
  /// The test run's data of n samples and the fits' estimates into z (row s
  /// = sample s), from the block's observations and counter phases
  /// (draw-major, extended_vectors_by_draw).
  void test_run_estimates(std::uint64_t first, std::size_t n, const std::vector<double>& observed,
                          const std::vector<double>& phases, Eigen::MatrixXd& z) const;

  const StudyConfig* config_;
  System system_;
  Sampler sampler_;
  TestRunOptions test_;
  bool needs_test_ = false, needs_alignment_data_ = false, needs_realignment_ = false;
  int k_ = 0;  // filter intervals
  Eigen::MatrixXd velocity_map_, position_map_;  // 3K × kDim (k = 1..K, axis-minor)
  /// The observation maps' columns as the block product takes them
  /// (kernels/map_product.h): kDim × (3K velocity | 3K position | 3 r(0) |
  /// 3 torquer commands | 3 alignment accelerometer outputs).
  Eigen::MatrixXd observation_columns_;
  int alignment_column() const { return 6 * k_ + 3; }  // the first of the alignment's six
  /// The estimators' rows as columns: K × 4 (4.8) and K × 3 (4.4).
  Eigen::MatrixXd position_fit_columns_, accel_fit_columns_;
  Eigen::MatrixXd nominal_velocity_, true_position_;  // 3 × (K+1)
  Sensitivity3 initial_position_;
  TestRunEstimators est_;
  Sensitivity3 torquer_map_, align_accel_map_;
  Vec3 earth_rate_command_;  // ω_in^n: the torquer command besides ω_c
  Eigen::MatrixXd g_;
  Eigen::VectorXd w_mean_, w_var_, w_m4_;
};

}  // namespace insmc::mc
