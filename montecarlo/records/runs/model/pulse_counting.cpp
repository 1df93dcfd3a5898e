#include "montecarlo/records/runs/model/pulse_counting.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
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
  std::vector<Vec3> nominal(G);
  std::vector<Sensitivity3> own(G);
  own[0].setZero();
  nominal[0] = nominal_velocity_increment(grid[0], site.model);
  for (std::size_t g = 1; g < G; ++g) {
    const double a = grid[g - 1], b = grid[g];
    own[g] = own[g - 1] + (b - a) / 6.0 * (model.forcing(a) + 4.0 * model.forcing(0.5 * (a + b)) + model.forcing(b));
    nominal[g] = nominal_velocity_increment(b, site.model);
  }
  const double ws = site.model.schuler_radps();
  std::vector<double> cos_mid(G), sin_mid(G);
  for (std::size_t g = 1; g < G; ++g) {
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

  Eigen::MatrixXd Q(static_cast<Eigen::Index>(r_rows.size()), kDraws);
  Draws draws(kSeed);
  const UncertaintyVector x_std = x_var.cwiseSqrt();
  for (int s = 0; s < kDraws; ++s) {
    UncertaintyVector x;
    for (int j = 0; j < uncertainty_slot::kDim; ++j) x[j] = x_std[j] * draws.normal();
    Vec3 phase;
    for (int k = 0; k < 3; ++k) phase[k] = draws.uniform() - 0.5;
    Vec3 v_prev = Vec3::Zero(), cos_sum = Vec3::Zero(), sin_sum = Vec3::Zero();
    Vec3 cos_at_reset = Vec3::Zero(), sin_at_reset = Vec3::Zero();
    for (std::size_t g = 1; g < G; ++g) {
      const Vec3 v = nominal[g] + own[g] * x;
      const double h = grid[g] - grid[g - 1];
      for (int k = 0; k < 3; ++k) {
        const double e = motion.velocity_rms_mps[k] >= 0.5 * w ? w * phase[k] * h  // cycling from the start
                                                                 : counting_velocity_error_integral(v_prev[k], v[k], h, phase[k], w);
        cos_sum[k] += cos_mid[g] * e;
        sin_sum[k] += sin_mid[g] * e;
      }
      v_prev = v;
      if (g == reset_at) cos_at_reset = cos_sum, sin_at_reset = sin_sum;
      // (3.24): r(t) = ∫ cos(ω_s (t − s)) e(s) ds, from T after a reset.
      const double c = std::cos(ws * grid[g]), sn = std::sin(ws * grid[g]);
      for (const auto& [k, j] : at[g]) {
        const bool from_reset = after_reset[static_cast<std::size_t>(j)];
        Q(j, s) = c * (cos_sum[k] - (from_reset ? cos_at_reset[k] : 0.0)) +
                  sn * (sin_sum[k] - (from_reset ? sin_at_reset[k] : 0.0));
      }
    }
    for (const auto& [k, j] : at[0]) Q(j, s) = 0.0;  // rows at t = 0
  }

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
