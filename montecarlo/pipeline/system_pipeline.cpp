#include "montecarlo/pipeline/system_pipeline.h"

#include <algorithm>
#include <cmath>

#include "lib/alignment/alignment.h"
#include "lib/propagation/linear_model.h"
#include "lib/preflight/instruments.h"
#include "lib/preflight/observables.h"
#include "lib/propagation/paper_model.h"
#include "montecarlo/random/philox.h"

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
  velocity_map_.resize(3 * k_, ux::kDim);
  position_map_.resize(3 * k_, ux::kDim);
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
  const Sensitivity3 steady = steady_state(system, c.map_fidelity(), m);
  torquer_map_ = torquer_commands(steady, m);
  align_accel_map_ = alignment_accelerometer_outputs(steady, m);
  const double w = m.earth_rate_radps;
  earth_rate_command_ = Vec3(w * std::cos(m.latitude_rad), 0.0, -w * std::sin(m.latitude_rad));  // (2.6)
  build_covariance_map(c, maps);
}

void SystemPipeline::extended_vectors(std::uint64_t first, std::size_t n, const Eigen::MatrixXd& x,
                                      Eigen::MatrixXd& z) const {
  const StudyConfig& c = *config_;
  const ModelOptions& m = c.model;
  const Eigen::Index ni = static_cast<Eigen::Index>(n);
  z.leftCols(ni).setZero();
  z.topLeftCorner(ux::kDim, ni) = x.leftCols(ni);
  if (needs_realignment_) {
    double u[kRealignDraws];
    for (std::size_t s = 0; s < n; ++s) {
      fill_uniform01(c.seed, Stream::Realignment, first + s, kRealignDraws, 1, u);
      for (int i = 0; i < kRealignDraws; ++i)
        z(kRealignedSlots[i].z_index, static_cast<Eigen::Index>(s)) = sampler_.transform_one(kRealignedSlots[i].x_index, u[i]);
    }
  }
  if (!needs_test_ && !needs_alignment_data_) return;
  const double g = m.gravity_mps2, T = test_.duration_s, tau = test_.filter_interval_s;
  const double dv = test_.dv_pulse_mps, q = test_.position_resolution_m;
  double phases[kPhaseDraws];
  // The observations of the block, in per-thread buffers kept across calls:
  // with a fresh 2 MB temporary per product, half of a paper run's time went
  // to page faults and zeroing of the new memory (perf, docs/performance.md).
  thread_local Eigen::MatrixXd vel_buffer, pos_buffer, r0_buffer;
  const auto product = [&](Eigen::MatrixXd& buffer, const auto& map) {
    if (buffer.rows() != map.rows() || buffer.cols() < ni)
      buffer.resize(map.rows(), std::max<Eigen::Index>(ni, static_cast<Eigen::Index>(kBlockSize)));
    buffer.leftCols(ni).noalias() = map * x.leftCols(ni);
    return buffer.leftCols(ni);
  };
  const auto vel = product(vel_buffer, velocity_map_);     // 3K × n
  const auto pos = product(pos_buffer, position_map_);     // 3K × n
  const auto r0 = product(r0_buffer, initial_position_);  // 3 × n
  Eigen::MatrixXd accel_data(k_, 3), pos_data(k_, 3), sway(k_ + 1, 3);
  const double sway_a = std::exp(-tau / test_.sway.correlation_time_s);
  for (std::size_t s = 0; s < n; ++s) {
    const Eigen::Index si = static_cast<Eigen::Index>(s);
    fill_uniform01(c.seed, Stream::PulsePhase, first + s, kPhaseDraws, 1, phases);
    if (needs_test_) {
      sway.setZero();
      if (test_.sway.enabled()) {  // first-order Gauss–Markov velocity wiggle per axis
        CounterStream normals(c.seed, Stream::Sway, first + s);
        const double sigma = test_.sway.velocity_rms_mps, b = sigma * std::sqrt(1 - sway_a * sway_a);
        for (int a = 0; a < 3; ++a) {
          sway(0, a) = sigma * normals.standard_normal();
          for (int k = 1; k <= k_; ++k) sway(k, a) = sway_a * sway(k - 1, a) + b * normals.standard_normal();
        }
      }
      for (int a = 0; a < 3; ++a) {
        // The counter sees nominal + error + sway velocity, with the
        // remainder at switch-over as its starting phase.
        DeltaVCounter counter(dv, phases[a] * dv);
        const PositionReadout readout(q, true_position_(a, 0), true_position_(a, 0) + r0(a, si));
        for (int k = 1; k <= k_; ++k) {
          const double v = nominal_velocity_(a, k) + vel(3 * (k - 1) + a, si) + sway(k, a) - sway(0, a);
          accel_data(k - 1, a) =
              counter.interval_error_mps2(v, nominal_velocity_(a, k) - nominal_velocity_(a, k - 1), tau);
          const double truth = true_position_(a, k);
          pos_data(k - 1, a) = readout.change_m(truth, truth + r0(a, si) + pos(3 * (k - 1) + a, si));
        }
      }
      const Eigen::Matrix<double, kEstimateRows, 3> u = apply_estimators<3>(est_, m, T, pos_data, accel_data);
      for (int a = 0; a < 3; ++a) {
        z(ez::kU2 + a, si) = u(kU2Row, a);
        z(ez::kU3 + a, si) = u(kU3Row, a);
        z(ez::kU3Accel + a, si) = u(kU3AccelRow, a);
        z(ez::kDfT + a, si) = u(kDfAtTestEndRow, a);
        z(ez::kWiggleAtT + a, si) = -sway(k_, a);  // computed − true velocity after the reset
      }
    }
    if (needs_alignment_data_) {
      const double ta = test_.alignment_average_s, dtheta = test_.torquer_pulse_rad;
      const Vec3 wc = torquer_map_ * x.col(si);
      const Vec3 df = align_accel_map_ * x.col(si);
      for (int a = 0; a < 3; ++a) {
        // Torquer commands (5.14) counted in angle pulses over ta, less the known earth-rate command.
        z(ez::kTorquerCommands + a, si) = counted_mean(wc[a], earth_rate_command_[a], ta, dtheta, phases[3 + a]);
        // Accelerometer outputs (5.18) counted in ΔV pulses over ta, less the expected −g on z.
        z(ez::kAlignAccel + a, si) = counted_mean(df[a], a == 2 ? -g : 0.0, ta, dv, phases[6 + a]);
      }
    }
  }
}

void SystemPipeline::build_covariance_map(const StudyConfig& c, const TestRunMaps& maps) {
  // Inputs w: x | fresh draws | position rounding e_{k,a} | ΔV counter
  // remainders U_{k,a} | sway normals n_{k,a} | torquer (φ, U) | alignment ΔV (φ, U).
  const int K = k_, n1 = K + 1;
  const int kx = 0, kr = ux::kDim, ke = kr + kRealignDraws, ku = ke + 3 * n1, kn = ku + 3 * n1, kt = kn + 3 * n1,
            kf = kt + 6, W = kf + 6;
  const ModelOptions& m = c.model;
  const double T = test_.duration_s, tau = test_.filter_interval_s;
  const double dv = test_.dv_pulse_mps, q = test_.position_resolution_m, dtheta = test_.torquer_pulse_rad;
  const double ta = test_.alignment_average_s;
  g_ = Eigen::MatrixXd::Zero(ez::kDim, W);
  w_mean_ = Eigen::VectorXd::Zero(W);
  w_var_ = Eigen::VectorXd::Zero(W);
  w_m4_ = Eigen::VectorXd::Zero(W);
  auto set_uniform = [&](int i, double lo, double hi) {
    const double h = hi - lo;
    w_mean_[i] = (lo + hi) / 2, w_var_[i] = h * h / 12, w_m4_[i] = h * h * h * h / 80;
  };
  g_.block(ez::kX, kx, ux::kDim, ux::kDim).setIdentity();
  for (int i = 0; i < ux::kDim; ++i) {
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
        pos_rows.block(k - 1, kx, 1, ux::kDim) = maps.position_change[k].row(a);
        pos_rows(k - 1, ke + 3 * k + a) += 1.0;
        pos_rows(k - 1, ke + a) -= 1.0;
        acc_rows.block(k - 1, kx, 1, ux::kDim) = (maps.velocity_increment[k].row(a) - maps.velocity_increment[k - 1].row(a)) / tau;
        acc_rows(k - 1, ku + 3 * (k - 1) + a) += 1.0 / tau;  // U_{k−1} − U_k
        acc_rows(k - 1, ku + 3 * k + a) -= 1.0 / tau;
        for (int j = 0; j < n1; ++j)
          acc_rows(k - 1, kn + 3 * j + a) += (l(k, j) - l(k - 1, j)) / tau;
      }
      const Eigen::MatrixXd u = apply_estimators(est_, m, T, pos_rows, acc_rows);
      g_.row(ez::kU2 + a) = u.row(kU2Row);
      g_.row(ez::kU3 + a) = u.row(kU3Row);
      g_.row(ez::kU3Accel + a) = u.row(kU3AccelRow);
      g_.row(ez::kDfT + a) = u.row(kDfAtTestEndRow);
      for (int j = 0; j < n1; ++j) g_(ez::kWiggleAtT + a, kn + 3 * j + a) = -l(K, j);
    }
  }
  if (needs_alignment_data_) {
    for (int a = 0; a < 3; ++a) {
      g_.block(ez::kTorquerCommands + a, kx, 1, ux::kDim) = torquer_map_.row(a);
      g_(ez::kTorquerCommands + a, kt + a) = 1.0 / ta;       // counter phase φ
      g_(ez::kTorquerCommands + a, kt + 3 + a) = -1.0 / ta;  // remainder at the end
      g_.block(ez::kAlignAccel + a, kx, 1, ux::kDim) = align_accel_map_.row(a);
      g_(ez::kAlignAccel + a, kf + a) = 1.0 / ta;
      g_(ez::kAlignAccel + a, kf + 3 + a) = -1.0 / ta;
    }
  }
}

}  // namespace insmc::mc
