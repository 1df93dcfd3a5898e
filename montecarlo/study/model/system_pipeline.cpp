#include "montecarlo/study/model/system_pipeline.h"

#include <algorithm>
#include <cmath>

#include "lib/alignment/alignment.h"
#include "lib/propagation/linear_model.h"
#include "lib/preflight/instruments.h"
#include "lib/preflight/observables.h"
#include "lib/propagation/paper_model.h"
#include "montecarlo/study/kernels/counter_kernels.h"
#include "montecarlo/study/kernels/map_product.h"
#include "montecarlo/study/random/philox.h"

namespace insmc::mc {
namespace {

// Uniforms of the PulsePhase stream per sample: the ΔV counters' remainders
// at switch-over (3), the torquer pulse counters' (3), the alignment-phase
// ΔV counters' (3).
constexpr int kPhaseDraws = 9;
constexpr int kRealignDraws = static_cast<int>(std::size(kRealignedSlots));


/// The steady-state misalignment during alignment at the chosen fidelity.
Sensitivity3 steady_state(System s, Fidelity f, const ModelOptions& m) {
  return f == Fidelity::kPaper ? simplified_steady_state_misalignment(s, m) : full_steady_state_misalignment(s, m);
}

}  // namespace

SystemPipeline::SystemPipeline(const StudyConfig& c, System system)
    : config_(&c), system_(system), sampler_(c.uncertainties), test_(c.test) {
  for (Scheme s : c.schemes) {
    needs_test_ |= uses_test_run(s);
    needs_alignment_data_ |= uses_alignment_data(s);
    needs_realignment_ |= realigns(s);
  }
  const ModelOptions& m = c.model;
  k_ = test_.intervals();
  const TestRunMaps maps = test_run_maps(system, c.map_fidelity(), m, test_);
  velocity_map_.resize(3 * k_, uncertainty_slot::kDim);
  position_map_.resize(3 * k_, uncertainty_slot::kDim);
  nominal_velocity_.resize(3, k_ + 1);
  true_position_.resize(3, k_ + 1);
  for (int k = 0; k <= k_; ++k) {
    nominal_velocity_.col(k) = nominal_velocity_increment(maps.t_s[k], m);
    true_position_.col(k) = true_position_ap(maps.t_s[k], m);
    if (k == 0) continue;
    velocity_map_.middleRows<3>(3 * (k - 1)) = maps.velocity_increment[k];
    position_map_.middleRows<3>(3 * (k - 1)) = maps.position_change[k];
  }
  initial_position_ = c.map_fidelity() == Fidelity::kPaper ? paper_short_run_matrices(system, m).initial_position_m
                                                     : LinearErrorModel(system, m).initial_position();
  const Resolvability r = resolvable_terms(system, m, test_, c.uncertainties);
  est_ = make_estimators(test_, m, r.u3, r.u4);
  position_fit_columns_ = est_.position.transpose();
  accel_fit_columns_ = est_.accel.transpose();
  const Sensitivity3 steady = steady_state(system, c.map_fidelity(), m);
  torquer_map_ = torquer_commands(steady, m);
  align_accel_map_ = alignment_accelerometer_outputs(steady, m);
  observation_columns_.resize(uncertainty_slot::kDim, alignment_column() + 6);
  observation_columns_ << velocity_map_.transpose(), position_map_.transpose(), initial_position_.transpose(),
      torquer_map_.transpose(), align_accel_map_.transpose();
  const double w = m.earth_rate_radps;
  earth_rate_command_ = Vec3(w * std::cos(m.latitude_rad), 0.0, -w * std::sin(m.latitude_rad));  // (2.6)
  build_covariance_map(c, maps);
}

void SystemPipeline::extended_vectors(std::uint64_t first, std::size_t n, const Eigen::MatrixXd& x,
                                      Eigen::MatrixXd& z) const {
  const Eigen::Index ni = static_cast<Eigen::Index>(n);
  thread_local std::vector<double> x_by_draw;
  thread_local Eigen::MatrixXd z_by_draw;
  x_by_draw.resize(n * uncertainty_slot::kDim);
  if (z_by_draw.rows() < ni) z_by_draw.resize(ni, z_slot::kDim);
  Eigen::Map<Eigen::MatrixXd>(x_by_draw.data(), ni, uncertainty_slot::kDim) = x.leftCols(ni).transpose();
  extended_vectors_by_draw(first, n, x_by_draw.data(), z_by_draw);
  z.leftCols(ni) = z_by_draw.topRows(ni).transpose();
}

void SystemPipeline::extended_vectors_by_draw(std::uint64_t first, std::size_t n, const double* x_by_draw,
                                              Eigen::MatrixXd& z) const {
  const StudyConfig& c = *config_;
  const Eigen::Index ni = static_cast<Eigen::Index>(n);
  z.topRows(ni).setZero();
  z.topLeftCorner(ni, uncertainty_slot::kDim) = Eigen::Map<const Eigen::MatrixXd>(x_by_draw, ni, uncertainty_slot::kDim);
  // The block's buffers, kept per thread across calls: with fresh temporaries
  // half of a paper run's time went to page faults and zeroing of new memory
  // (perf, docs/performance.md). Every block is draw-major: value i of
  // sample s at [i·n + s], so each step below runs over the samples of the
  // block as one vectorised loop or block product, and each sample's values
  // depend on that sample alone (the same bits in any block: map_product.h).
  thread_local std::vector<double> draws;
  if (needs_realignment_) {
    draws.resize(n * kRealignDraws);
    fill_uniform01_draw_major(c.seed, Stream::Realignment, first, kRealignDraws, n, draws);
    for (int i = 0; i < kRealignDraws; ++i)
      for (std::size_t s = 0; s < n; ++s)
        z(static_cast<Eigen::Index>(s), kRealignedSlots[i].z_index) =
            sampler_.transform_one(kRealignedSlots[i].x_index, draws[static_cast<std::size_t>(i) * n + s]);
  }
  if (!needs_test_ && !needs_alignment_data_) return;
  // The observations: ΔV and Δr per interval and axis, r(0), the alignment's
  // torquer commands and accelerometer outputs (only these without the test run).
  thread_local std::vector<double> observed, phases;
  const int first_column = needs_test_ ? 0 : alignment_column();
  const int columns = static_cast<int>(observation_columns_.cols()) - first_column;
  observed.resize(n * static_cast<std::size_t>(observation_columns_.cols()));
  map_product({n, uncertainty_slot::kDim, columns}, x_by_draw, n, observation_columns_.col(first_column).data(), uncertainty_slot::kDim,
              observed.data() + static_cast<std::size_t>(first_column) * n, n);
  phases.resize(n * kPhaseDraws);
  fill_uniform01_draw_major(c.seed, Stream::PulsePhase, first, kPhaseDraws, n, phases);
  if (needs_test_) test_run_estimates(first, n, observed, phases, z);
  if (needs_alignment_data_) {
    const ModelOptions& m = c.model;
    const double ta = test_.alignment_average_s, dtheta = test_.torquer_pulse_rad, dv = test_.dv_pulse_mps;
    const std::size_t base = static_cast<std::size_t>(alignment_column());
    for (int a = 0; a < 3; ++a) {
      const auto ua = static_cast<std::size_t>(a);
      const double* wc = observed.data() + (base + ua) * n;
      const double* df = observed.data() + (base + 3 + ua) * n;
      const double* torquer_phase = phases.data() + (3 + ua) * n;
      const double* accel_phase = phases.data() + (6 + ua) * n;
      for (std::size_t s = 0; s < n; ++s) {
        const Eigen::Index si = static_cast<Eigen::Index>(s);
        // Torquer commands (5.14) counted in angle pulses over ta, less the known earth-rate command.
        z(si, z_slot::kTorquerCommands + a) = counted_mean(wc[s], earth_rate_command_[a], ta, dtheta, torquer_phase[s]);
        // Accelerometer outputs (5.18) counted in ΔV pulses over ta, less the expected −g on z.
        z(si, z_slot::kAlignAccel + a) = counted_mean(df[s], a == 2 ? -m.gravity_mps2 : 0.0, ta, dv, accel_phase[s]);
      }
    }
  }
}

void SystemPipeline::test_run_estimates(std::uint64_t first, std::size_t n, const std::vector<double>& observed,
                                        const std::vector<double>& phases, Eigen::MatrixXd& z) const {
  const StudyConfig& c = *config_;
  const ModelOptions& m = c.model;
  const double T = test_.duration_s, tau = test_.filter_interval_s;
  const double dv = test_.dv_pulse_mps, q = test_.position_resolution_m;
  const std::size_t K = static_cast<std::size_t>(k_), rows_3k = 3 * K;
  const auto column = [&](std::size_t i) { return observed.data() + i * n; };
  // Sway: a first-order Gauss–Markov velocity wiggle per axis, sample by
  // sample from its own stream, held as sway[(3k + a)·n + s], k = 0..K.
  thread_local std::vector<double> sway;
  const bool swaying = test_.sway.enabled();
  if (swaying) {
    sway.resize(3 * (K + 1) * n);
    const double a_gm = std::exp(-tau / test_.sway.correlation_time_s);
    const double sigma = test_.sway.velocity_rms_mps, b = sigma * std::sqrt(1 - a_gm * a_gm);
    for (std::size_t s = 0; s < n; ++s) {
      CounterStream normals(c.seed, Stream::Sway, first + s);
      for (std::size_t a = 0; a < 3; ++a) {
        sway[a * n + s] = sigma * normals.standard_normal();
        for (std::size_t k = 1; k <= K; ++k)
          sway[(3 * k + a) * n + s] = a_gm * sway[(3 * (k - 1) + a) * n + s] + b * normals.standard_normal();
      }
    }
  }
  thread_local std::vector<double> accel_data, pos_data, counted, first_reading, u_pos, u_acc;
  accel_data.resize(K * n), pos_data.resize(K * n), counted.resize(n), first_reading.resize(n);
  u_pos.resize(4 * n), u_acc.resize(3 * n);
  for (std::size_t a = 0; a < 3; ++a) {
    const int ia = static_cast<int>(a);
    // The ΔV counter sees nominal + error + sway velocity, with the remainder
    // at switch-over (phase) as its starting point; each interval's datum is
    // the counted increment less the nominal one, over τ (DeltaVCounter).
    const ProductKernel kernel = best_product_kernel();
    std::fill(counted.begin(), counted.end(), 0.0);
    for (std::size_t k = 1; k <= K; ++k) {
      PulseInterval interval;
      interval.error = column(3 * (k - 1) + a);
      interval.sway_now = swaying ? sway.data() + (3 * k + a) * n : nullptr;
      interval.sway_start = swaying ? sway.data() + a * n : nullptr;
      interval.phase01 = phases.data() + a * n;
      interval.nominal_mps = nominal_velocity_(ia, static_cast<Eigen::Index>(k));
      interval.increment_mps = interval.nominal_mps - nominal_velocity_(ia, static_cast<Eigen::Index>(k - 1));
      interval.pulse_mps = dv;
      interval.interval_s = tau;
      count_pulses(kernel, interval, n, counted.data(), accel_data.data() + (k - 1) * n);
    }
    // The position computer's readings, each as a change from the first (PositionReadout).
    PositionReadings readings{column(2 * rows_3k + a), nullptr, nullptr, true_position_(ia, 0), q};
    read_positions(kernel, readings, n, first_reading.data());
    readings.first = first_reading.data();
    for (std::size_t k = 1; k <= K; ++k) {
      readings.error = column(rows_3k + 3 * (k - 1) + a);
      readings.truth_m = true_position_(ia, static_cast<Eigen::Index>(k));
      read_positions(kernel, readings, n, pos_data.data() + (k - 1) * n);
    }
    // The least-squares fits (4.8), (4.4) on every sample's K data at once.
    map_product({n, k_, 4}, pos_data.data(), n, position_fit_columns_.data(), K, u_pos.data(), n);
    map_product({n, k_, 3}, accel_data.data(), n, accel_fit_columns_.data(), K, u_acc.data(), n);
    for (std::size_t s = 0; s < n; ++s) {
      const Eigen::Index si = static_cast<Eigen::Index>(s);
      z(si, z_slot::kU2 + ia) = u_pos[n + s];
      z(si, z_slot::kU3 + ia) = u_pos[2 * n + s];
      z(si, z_slot::kU3Accel + ia) = u_acc[n + s];
      z(si, z_slot::kDfT + ia) = filtered_df_at_test_end(m, T, u_acc[s], u_acc[n + s], u_acc[2 * n + s]);
      // Computed − true velocity after the reset.
      z(si, z_slot::kWiggleAtT + ia) = swaying ? -sway[(3 * K + a) * n + s] : -0.0;
    }
  }
}

void SystemPipeline::build_covariance_map(const StudyConfig& c, const TestRunMaps& maps) {
  // Inputs w: x | fresh draws | position rounding e_{k,a} | ΔV counter
  // remainders U_{k,a} | sway normals n_{k,a} | torquer (φ, U) | alignment ΔV (φ, U).
  const int K = k_, n1 = K + 1;
  const int kx = 0, kr = uncertainty_slot::kDim, ke = kr + kRealignDraws, ku = ke + 3 * n1, kn = ku + 3 * n1, kt = kn + 3 * n1,
            kf = kt + 6, W = kf + 6;
  const ModelOptions& m = c.model;
  const double T = test_.duration_s, tau = test_.filter_interval_s;
  const double dv = test_.dv_pulse_mps, q = test_.position_resolution_m, dtheta = test_.torquer_pulse_rad;
  const double ta = test_.alignment_average_s;
  g_ = Eigen::MatrixXd::Zero(z_slot::kDim, W);
  w_mean_ = Eigen::VectorXd::Zero(W);
  w_var_ = Eigen::VectorXd::Zero(W);
  w_m4_ = Eigen::VectorXd::Zero(W);
  auto set_uniform = [&](int i, double lo, double hi) {
    const double h = hi - lo;
    w_mean_[i] = (lo + hi) / 2, w_var_[i] = h * h / 12, w_m4_[i] = h * h * h * h / 80;
  };
  g_.block(z_slot::kX, kx, uncertainty_slot::kDim, uncertainty_slot::kDim).setIdentity();
  for (int i = 0; i < uncertainty_slot::kDim; ++i) {
    const ParameterDistribution& p = c.uncertainties.at(i);
    w_mean_[i] = p.mean(), w_var_[i] = p.variance(), w_m4_[i] = p.fourth_central_moment();
  }
  for (int i = 0; i < kRealignDraws; ++i) {
    g_(kRealignedSlots[i].z_index, kr + i) = needs_realignment_ ? 1.0 : 0.0;
    const ParameterDistribution& p = c.uncertainties.at(kRealignedSlots[i].x_index);
    w_mean_[kr + i] = p.mean(), w_var_[kr + i] = p.variance(), w_m4_[kr + i] = p.fourth_central_moment();
  }
  for (int i = 0; i < 3 * n1; ++i) {
    set_uniform(ke + i, -q / 2, q / 2);
    set_uniform(ku + i, 0.0, dv);
    w_var_[kn + i] = test_.sway.enabled() ? 1.0 : 0.0, w_m4_[kn + i] = test_.sway.enabled() ? 3.0 : 0.0;
  }
  for (int i = 0; i < 6; ++i) set_uniform(kt + i, 0.0, dtheta), set_uniform(kf + i, 0.0, dv);
  if (needs_test_) {
    // Data rows as maps of w: position Δr_{k,a} and filtered Δf_{k,a}.
    const double a_gm = std::exp(-tau / test_.sway.correlation_time_s);
    const double sigma = test_.sway.velocity_rms_mps, b = sigma * std::sqrt(1 - a_gm * a_gm);
    // Sway velocity v_{k,a} = Σ_j L_{kj} n_{j,a} (first-order Gauss–Markov).
    Eigen::MatrixXd l = Eigen::MatrixXd::Zero(n1, n1);
    l(0, 0) = sigma;
    for (int k = 1; k < n1; ++k) {
      l.row(k) = a_gm * l.row(k - 1);
      l(k, k) = b;
    }
    for (int a = 0; a < 3; ++a) {
      Eigen::MatrixXd pos_rows = Eigen::MatrixXd::Zero(K, W), acc_rows = Eigen::MatrixXd::Zero(K, W);
      for (int k = 1; k <= K; ++k) {
        pos_rows.block(k - 1, kx, 1, uncertainty_slot::kDim) = maps.position_change[k].row(a);
        pos_rows(k - 1, ke + 3 * k + a) += 1.0;
        pos_rows(k - 1, ke + a) -= 1.0;
        acc_rows.block(k - 1, kx, 1, uncertainty_slot::kDim) = (maps.velocity_increment[k].row(a) - maps.velocity_increment[k - 1].row(a)) / tau;
        acc_rows(k - 1, ku + 3 * (k - 1) + a) += 1.0 / tau;  // U_{k−1} − U_k
        acc_rows(k - 1, ku + 3 * k + a) -= 1.0 / tau;
        for (int j = 0; j < n1; ++j)
          acc_rows(k - 1, kn + 3 * j + a) += (l(k, j) - l(k - 1, j)) / tau;
      }
      const Eigen::MatrixXd u = apply_estimators(est_, m, T, pos_rows, acc_rows);
      g_.row(z_slot::kU2 + a) = u.row(kU2Row);
      g_.row(z_slot::kU3 + a) = u.row(kU3Row);
      g_.row(z_slot::kU3Accel + a) = u.row(kU3AccelRow);
      g_.row(z_slot::kDfT + a) = u.row(kDfAtTestEndRow);
      for (int j = 0; j < n1; ++j) g_(z_slot::kWiggleAtT + a, kn + 3 * j + a) = -l(K, j);
    }
  }
  if (needs_alignment_data_) {
    for (int a = 0; a < 3; ++a) {
      g_.block(z_slot::kTorquerCommands + a, kx, 1, uncertainty_slot::kDim) = torquer_map_.row(a);
      g_(z_slot::kTorquerCommands + a, kt + a) = 1.0 / ta;       // counter phase φ
      g_(z_slot::kTorquerCommands + a, kt + 3 + a) = -1.0 / ta;  // remainder at the end
      g_.block(z_slot::kAlignAccel + a, kx, 1, uncertainty_slot::kDim) = align_accel_map_.row(a);
      g_(z_slot::kAlignAccel + a, kf + a) = 1.0 / ta;
      g_(z_slot::kAlignAccel + a, kf + 3 + a) = -1.0 / ta;
    }
  }
}

}  // namespace insmc::mc
