#include "montecarlo/records/runs/model/response.h"

#include <algorithm>
#include <array>

#include "lib/frames/frames.h"
#include "lib/propagation/linear_model.h"

namespace insmc::runs {
namespace {

/// Composite Simpson weights over 4 sub-intervals: the window mean of a
/// smooth forcing to ~1e-9 relative for τ = 10 s against the earth rate.
constexpr double kSimpson[5] = {1.0 / 12, 4.0 / 12, 2.0 / 12, 4.0 / 12, 1.0 / 12};

/// The Schuler loop's Runge–Kutta step: 2 s (ω_s h = 0.0025), or longer for
/// runs beyond 11 h so that a run costs at most 20,000 steps (h = 8.6 s over
/// 48 h: ω_s h = 0.011, a relative error of (ω_s h)^4/120 per step, 1e-10).
double schuler_step_s(const Layout& layout) {
  constexpr double kStepS = 2.0;
  constexpr double kMaxSteps = 20000.0;
  double end = 0.0;
  for (std::size_t i = 0; i < layout.rows.size(); ++i) end = std::max(end, layout.clock_s(i));
  return std::max(kStepS, end / kMaxSteps);
}

/// Fills `out` (rows × cols) from a forcing t -> 3 × cols map: f rows the
/// window mean of the forcing, r rows the Schuler loop (3.24) from the
/// initial maps at switch-over. After a scheme (layout.h) the navigation
/// rows start their own loop: from a zero state at T after a reset (the
/// forcing goes on), from switch-over on their own clock after a restart.
template <class Map, class Forcing>
void fill_rows(const Layout& layout, const RecordSite& site, const Forcing& forcing, bool f_responds,
               const Map& zero, const Map& r0, const Map& v0, Eigen::MatrixXd& out) {
  const double tau = site.filter_interval_s;
  // r rows per loop: 0 from switch-over, 1 from the reset at T, 2 the restarted navigation.
  std::array<std::vector<double>, 3> r_times;
  const auto loop_of = [&](std::size_t i) {
    if (static_cast<int>(i) < layout.test_rows || layout.nav == NavSegment::kContinue) return 0;
    return layout.nav == NavSegment::kReset ? 1 : 2;
  };
  for (std::size_t i = 0; i < layout.rows.size(); ++i) {
    const ObservationRow& row = layout.rows[i];
    const double t = layout.clock_s(i);
    if (row.quantity == Quantity::kR) {
      r_times[static_cast<std::size_t>(loop_of(i))].push_back(t);
      continue;
    }
    if (!f_responds) {
      out.row(static_cast<Eigen::Index>(i)).setZero();
      continue;
    }
    Map mean = zero;
    for (int j = 0; j < 5; ++j) mean += kSimpson[j] * forcing(t - tau + 0.25 * tau * j);
    out.row(static_cast<Eigen::Index>(i)) = mean.row(row.axis);
  }
  std::array<std::vector<Map>, 3> r;
  for (std::size_t loop = 0; loop < 3; ++loop) {
    std::vector<double>& times = r_times[loop];
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    if (times.empty()) continue;
    const bool reset = loop == 1;
    r[loop] = integrate_schuler_maps<Map>(forcing, reset ? zero : r0, reset ? zero : v0, times,
                                          site.model.schuler_radps(), schuler_step_s(layout),
                                          reset ? layout.nav_start_s : 0.0);
  }
  for (std::size_t i = 0; i < layout.rows.size(); ++i) {
    const ObservationRow& row = layout.rows[i];
    if (row.quantity != Quantity::kR) continue;
    const auto loop = static_cast<std::size_t>(loop_of(i));
    const auto k = std::lower_bound(r_times[loop].begin(), r_times[loop].end(), layout.clock_s(i)) - r_times[loop].begin();
    out.row(static_cast<Eigen::Index>(i)) = r[loop][static_cast<std::size_t>(k)].row(row.axis);
  }
}

Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

Eigen::Vector3d gravity_in_ap(double t_s, const ModelOptions& model) {
  return model.gravity_mps2 * C_ap_n(model.latitude_rad, model.earth_rate_radps * t_s).col(2);
}

Eigen::MatrixXd uncertainty_response(const Layout& layout, const RecordSite& site) {
  const LinearErrorModel model(site.system, site.model);
  Eigen::MatrixXd out(static_cast<Eigen::Index>(layout.rows.size()), uncertainty_slot::kDim);
  // f rows: the forcing; r rows: (3.24) from δr(0), δV(0) of (3.22), (3.23).
  fill_rows<Sensitivity3>(layout, site, [&](double t) { return model.forcing(t); }, true,
                          Sensitivity3::Zero(), model.initial_position(), model.initial_velocity(), out);
  return out;
}

Eigen::MatrixXd input_response(const Layout& layout, const RecordSite& site, const InputSignal& input) {
  const int m = input.columns;
  Eigen::MatrixXd out(static_cast<Eigen::Index>(layout.rows.size()), m);
  Columns3 accel(3, m), angle(3, m);
  const auto forcing = [&](double t) -> Columns3 {
    input.at(std::max(t, 0.0), accel, angle);
    // (3.24): u = a − (C g_e) × θ.
    return accel - cross_matrix(gravity_in_ap(t, site.model)) * angle;
  };
  const Columns3 zero = Columns3::Zero(3, m);
  fill_rows<Columns3>(layout, site, forcing, input.f_responds, zero, zero, zero, out);
  return out;
}

}  // namespace insmc::runs
