#include "montecarlo/records/runs/model/pulse_counting.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "lib/common/input_error.h"
#include "lib/preflight/test_run.h"
#include "lib/propagation/linear_model.h"

namespace insmc::runs {
namespace {

constexpr int kDraws = 256;            // runs drawn for the r-row covariance
constexpr double kStepS = 5.0;         // counting steps (closed form within each)
/// At most this many steps a run: beyond 5.5 h the steps grow, so that a
/// run's counting costs what its rows do, not its hours (the slow axes,
/// whose sawtooth the columns carry, change little within a longer step).
constexpr double kMaxSteps = 4000.0;
constexpr int kMaxColumns = 32;
constexpr double kKeptComponent = 0.5;  // in units of a row's scale², summed over rows
constexpr std::uint64_t kSeed = 0x19690521ULL;

/// Uniform and normal draws from the 64-bit Mersenne twister, whose sequence
/// the standard fixes; the transforms are written here (the library's
/// distributions are not), so the draws are the same on every platform.
class Draws {
 public:
  explicit Draws(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double normal() {
    const double u = 1.0 - uniform(), v = uniform();  // u in (0, 1]
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
  }

 private:
  std::mt19937_64 engine_;
};

/// S(y) = (y − round(y))²/2, an antiderivative of the sawtooth y − round(y).
double sawtooth_antiderivative(double y) {
  const double d = y - std::round(y);
  return 0.5 * d * d;
}

}  // namespace

double counting_velocity_error(double v, double phase, double w) {
  const double y = phase + v / w;
  return w * (std::round(y) - y) + w * phase;
}

double counting_velocity_error_integral(double v0, double v1, double h, double phase, double w) {
  const double y0 = phase + v0 / w, y1 = phase + v1 / w;
  double sawtooth = 0.0;  // ∫ (round(y) − y) dt over the step
  if (std::abs(y1 - y0) < 1e-9) {
    sawtooth = (std::round(0.5 * (y0 + y1)) - 0.5 * (y0 + y1)) * h;
  } else {
    sawtooth = h / (y1 - y0) * (sawtooth_antiderivative(y0) - sawtooth_antiderivative(y1));
  }
  return w * (sawtooth + phase * h);
}

PulseCounting pulse_counting(const Layout& layout, const RecordSite& site, double w,
                             const UncertaintyVector& x_var, const Eigen::VectorXd& row_scale,
                             const CountedMotion& motion) {
  const auto n = static_cast<Eigen::Index>(layout.rows.size());
  if (layout.nav == NavSegment::kRestart && layout.test_rows < n) {
    // After a realignment the second navigation has counters of its own.
    const Layout test = layout.test_part(), nav = layout.restarted_part();
    const auto nt = static_cast<Eigen::Index>(layout.test_rows);
    const PulseCounting a = pulse_counting(test, site, w, x_var, row_scale.head(nt), motion);
    const PulseCounting b = pulse_counting(nav, site, w, x_var, row_scale.tail(n - nt), motion);
    PulseCounting out;
    out.columns = Eigen::MatrixXd::Zero(n, a.columns.cols() + b.columns.cols());
    out.columns.topLeftCorner(nt, a.columns.cols()) = a.columns;
    out.columns.bottomRightCorner(n - nt, b.columns.cols()) = b.columns;
    out.noise_var.resize(n);
    out.noise_var << a.noise_var, b.noise_var;
    return out;
  }
  PulseCounting out;
  out.noise_var = Eigen::VectorXd::Zero(n);
  out.columns.resize(n, 0);
  if (!(w > 0)) return out;
  const double tau = site.filter_interval_s;
  std::vector<Eigen::Index> r_rows;
  double end = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const ObservationRow& row = layout.rows[static_cast<std::size_t>(i)];
    if (row.quantity == Quantity::kF) {
      out.noise_var[i] = w * w / (6.0 * tau * tau);  // two independent remainders per window
    } else {
      r_rows.push_back(i);
      end = std::max(end, row.t_s);
    }
  }
  if (r_rows.empty()) return out;

  // Steps of at most step_s that land on every r-row time. The record
  // reader holds times within 48 h; the check keeps this loop bounded for
  // layouts built any other way.
  if (!(end <= magnitude_limit(Dimension::kTime)))
    throw InputError("record row time", format_quantity(end, Dimension::kTime),
                     "must lie within " + format_quantity(magnitude_limit(Dimension::kTime), Dimension::kTime));
  std::vector<double> grid;
  const double step_s = std::max(kStepS, end / kMaxSteps);
  for (double t = 0.0; t < end; t += step_s) grid.push_back(t);
  for (Eigen::Index i : r_rows) grid.push_back(layout.rows[static_cast<std::size_t>(i)].t_s);
  // After a reset at T the position integral starts again there (the
  // counters go on).
  const bool reset = layout.nav == NavSegment::kReset;
  if (reset) grid.push_back(layout.nav_start_s);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end(), [](double a, double b) { return b - a < 1e-9; }), grid.end());
  const std::size_t G = grid.size();
  // The specific force the counters integrate: the nominal one of a vehicle
  // at rest plus the run's own accelerometer output error (the forcing of
  // (3.24) per unit of x, integrated by Simpson's rule).
  const LinearErrorModel model(site.system, site.model);
  const double ws = site.model.schuler_radps();
  // The Schuler phase (3.24) at each grid point and each step's midpoint:
  // the same for every draw.
  std::vector<double> cos_at(G), sin_at(G), cos_mid(G), sin_mid(G);
  for (std::size_t g = 0; g < G; ++g) {
    cos_at[g] = std::cos(ws * grid[g]), sin_at[g] = std::sin(ws * grid[g]);
    if (g == 0) continue;
    const double m = 0.5 * (grid[g - 1] + grid[g]);
    cos_mid[g] = std::cos(ws * m), sin_mid[g] = std::sin(ws * m);
  }
  const std::size_t reset_at = reset ? static_cast<std::size_t>(std::lower_bound(grid.begin(), grid.end(),
                                                                                 layout.nav_start_s - 1e-9) - grid.begin())
                                     : G;
  // r rows ending at each grid point, per axis.
  std::vector<std::vector<std::pair<int, int>>> at(G);  // (axis, index into r_rows)
  std::vector<bool> after_reset(r_rows.size(), false);
  for (std::size_t j = 0; j < r_rows.size(); ++j) {
    const ObservationRow& row = layout.rows[static_cast<std::size_t>(r_rows[j])];
    after_reset[j] = reset && r_rows[j] >= layout.test_rows;
    const auto g = static_cast<std::size_t>(
        std::lower_bound(grid.begin(), grid.end(), row.t_s - 1e-9) - grid.begin());
    at[g].emplace_back(row.axis, static_cast<int>(j));
  }

  // The runs drawn, in the stream's order: x, then the three pulse phases.
  Draws draws(kSeed);
  const UncertaintyVector x_std = x_var.cwiseSqrt();
  Eigen::MatrixXd X(uncertainty_slot::kDim, kDraws), phase(3, kDraws);
  for (int s = 0; s < kDraws; ++s) {
    for (int j = 0; j < uncertainty_slot::kDim; ++j) X(j, s) = x_std[j] * draws.normal();
    for (int k = 0; k < 3; ++k) phase(k, s) = draws.uniform() - 0.5;
  }
  // An axis whose counters cycle from the start (sway of half a pulse or
  // more) does not read its increment V: where every axis does, no
  // increment is computed.
  std::array<bool, 3> cycling{};
  for (int k = 0; k < 3; ++k) cycling[static_cast<std::size_t>(k)] = motion.velocity_rms_mps[k] >= 0.5 * w;
  const bool needs_increment = !(cycling[0] && cycling[1] && cycling[2]);

  // Each draw's running sums; the steps are taken a block at a time, so that
  // the increments of every draw are one matrix product (the sensitivities
  // of a block times the draws) and only a block of them is held.
  constexpr std::size_t kBlock = 64;
  Eigen::MatrixXd v_prev = Eigen::MatrixXd::Zero(3, kDraws), cos_sum = v_prev, sin_sum = v_prev;
  Eigen::MatrixXd cos_at_reset = v_prev, sin_at_reset = v_prev;
  Eigen::MatrixXd own_block(3 * static_cast<Eigen::Index>(kBlock), uncertainty_slot::kDim);
  Eigen::MatrixXd v_block = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(kBlock), kDraws);
  Eigen::MatrixXd Q(static_cast<Eigen::Index>(r_rows.size()), kDraws);
  Sensitivity3 own = Sensitivity3::Zero();
  Sensitivity3 forcing_prev = model.forcing(grid[0]);
  for (std::size_t g0 = 1; g0 < G; g0 += kBlock) {
    const std::size_t nb = std::min(kBlock, G - g0);
    const auto rows3 = 3 * static_cast<Eigen::Index>(nb);
    for (std::size_t j = 0; j < nb; ++j) {
      const std::size_t g = g0 + j;
      const double a = grid[g - 1], b = grid[g];
      const Sensitivity3 forcing_b = model.forcing(b);
      own += (b - a) / 6.0 * (forcing_prev + 4.0 * model.forcing(0.5 * (a + b)) + forcing_b);
      forcing_prev = forcing_b;
      own_block.middleRows(3 * static_cast<Eigen::Index>(j), 3) = own;
    }
    if (needs_increment) {
      v_block.topRows(rows3).noalias() = own_block.topRows(rows3) * X;
      for (std::size_t j = 0; j < nb; ++j)
        v_block.middleRows(3 * static_cast<Eigen::Index>(j), 3).colwise() +=
            nominal_velocity_increment(grid[g0 + j], site.model);
    }
    for (Eigen::Index s = 0; s < kDraws; ++s) {
      for (std::size_t j = 0; j < nb; ++j) {
        const std::size_t g = g0 + j;
        const double h = grid[g] - grid[g - 1];
        for (int k = 0; k < 3; ++k) {
          const double v = v_block(3 * static_cast<Eigen::Index>(j) + k, s);
          const double e = cycling[static_cast<std::size_t>(k)]
                               ? w * phase(k, s) * h
                               : counting_velocity_error_integral(v_prev(k, s), v, h, phase(k, s), w);
          cos_sum(k, s) += cos_mid[g] * e;
          sin_sum(k, s) += sin_mid[g] * e;
          v_prev(k, s) = v;
        }
        if (g == reset_at) cos_at_reset.col(s) = cos_sum.col(s), sin_at_reset.col(s) = sin_sum.col(s);
        // (3.24): r(t) = ∫ cos(ω_s (t − s)) e(s) ds, from T after a reset.
        for (const auto& [k, jr] : at[g]) {
          const bool from_reset = after_reset[static_cast<std::size_t>(jr)];
          Q(jr, s) = cos_at[g] * (cos_sum(k, s) - (from_reset ? cos_at_reset(k, s) : 0.0)) +
                     sin_at[g] * (sin_sum(k, s) - (from_reset ? sin_at_reset(k, s) : 0.0));
        }
      }
    }
  }
  for (const auto& [k, j] : at[0]) Q.row(j).setZero();  // rows at t = 0

  // Leading components of the draws' second moments as columns, the rest noise.
  Eigen::VectorXd scale(Q.rows());
  for (std::size_t j = 0; j < r_rows.size(); ++j) scale[static_cast<Eigen::Index>(j)] = row_scale[r_rows[j]];
  Q /= std::sqrt(static_cast<double>(kDraws));
  const Eigen::MatrixXd scaled = scale.cwiseInverse().asDiagonal() * Q;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled.transpose() * scaled);
  Eigen::VectorXd rest = Q.rowwise().squaredNorm();
  std::vector<Eigen::VectorXd> kept;
  for (Eigen::Index c = kDraws - 1; c >= 0 && static_cast<int>(kept.size()) < kMaxColumns; --c) {
    if (eig.eigenvalues()[c] < kKeptComponent) break;
    kept.push_back(Q * eig.eigenvectors().col(c));  // Q v: its variance is its square
    rest -= kept.back().cwiseAbs2();
  }
  out.columns = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t c = 0; c < kept.size(); ++c)
    for (std::size_t j = 0; j < r_rows.size(); ++j)
      out.columns(r_rows[j], static_cast<Eigen::Index>(c)) = kept[c][static_cast<Eigen::Index>(j)];
  for (std::size_t j = 0; j < r_rows.size(); ++j)
    out.noise_var[r_rows[j]] = std::max(0.0, rest[static_cast<Eigen::Index>(j)]);
  return out;
}

}  // namespace insmc::runs
