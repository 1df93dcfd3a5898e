#include "montecarlo/records/runs/model/scheme_rows.h"

#include <cmath>

#include "lib/alignment/alignment.h"
#include "lib/compensation/compensation_maps.h"
#include "lib/propagation/linear_model.h"

namespace insmc::runs {

TestRunOptions record_test_options(const RecordSite& site) {
  TestRunOptions t;
  t.duration_s = site.test_duration_s;
  t.filter_interval_s = site.filter_interval_s;
  t.dv_pulse_mps = site.dv_pulse_mps;
  t.position_resolution_m = site.position_resolution_m;
  return t;
}

SchemeRows scheme_rows(const Layout& layout, const RecordSite& site, const TestRunEstimators& estimators) {
  const auto n = static_cast<Eigen::Index>(layout.rows.size());
  SchemeRows s;
  s.replaced.assign(layout.rows.size(), false);
  s.x_columns = Eigen::MatrixXd::Zero(n, uncertainty_slot::kDim);
  s.estimate_map = Eigen::MatrixXd::Zero(n, kEstimateCount);
  s.columns.resize(n, 0);
  const Scheme scheme = site.scheme;
  if (scheme == Scheme::kNone) return s;
  const TestRunOptions test = record_test_options(site);
  const double T = site.test_duration_s;
  // The r rows after the scheme on its clock (clock_of): 5.4 acts from
  // switch-over, 5.2 and 5.3 from T, a realignment from the second switch-over.
  const double zero = clock_start_s(scheme, T, site.nav_start_s);
  std::vector<std::size_t> rows;
  std::vector<double> clock;
  for (std::size_t i = 0; i < layout.rows.size(); ++i) {
    if (layout.rows[i].quantity != Quantity::kR) continue;
    if (!uses_alignment_data(scheme) && static_cast<int>(i) < layout.test_rows) continue;
    rows.push_back(i);
    clock.push_back(layout.rows[i].t_s - zero);
  }
  const SchemeMaps maps = scheme_position_maps(scheme, site.system, Fidelity::kLinear, site.model, test, clock);

  // Columns beside x: fresh draws, r(0)'s rounding, 5.4's counting noise.
  std::vector<Eigen::VectorXd> extra;
  const auto add_column = [&](int x_index, double variance) {
    extra.push_back(Eigen::VectorXd::Zero(n));
    s.x_index.push_back(x_index);
    s.variance.conservativeResize(static_cast<Eigen::Index>(extra.size()));
    s.variance[static_cast<Eigen::Index>(extra.size() - 1)] = variance;
    return extra.size() - 1;
  };
  std::vector<std::size_t> fresh, rounding, counting;
  if (realigns(scheme))
    for (const RealignedSlot& slot : kRealignedSlots) fresh.push_back(add_column(slot.x_index, 0.0));
  // The position estimator fits Δr = r − r(0); from the record's r it fits
  // r, so each estimate carries c r(0) besides, c the estimator applied to
  // a constant (4.7), (4.8).
  const double q = site.position_resolution_m;
  Eigen::Vector4d per_r0 = Eigen::Vector4d::Zero();
  Sensitivity3 r0_map = Sensitivity3::Zero();
  if (uses_test_run(scheme)) {
    per_r0 = estimators.position * Eigen::VectorXd::Ones(estimators.position.cols());
    r0_map = LinearErrorModel(site.system, site.model).initial_position();
    for (int b = 0; b < 3 && q > 0; ++b) rounding.push_back(add_column(-1, q * q / 12.0));
  }
  // 5.4: the measured torquer commands (5.14) and accelerometer outputs
  // (5.19), each a map of x plus two pulse remainders over the averaging time.
  Eigen::Matrix<double, 6, uncertainty_slot::kDim> measured = Eigen::Matrix<double, 6, uncertainty_slot::kDim>::Zero();
  if (uses_alignment_data(scheme)) {
    const Sensitivity3 steady = full_steady_state_misalignment(site.system, site.model);
    measured.topRows<3>() = torquer_commands(steady, site.model);
    measured.bottomRows<3>() = alignment_accelerometer_outputs(steady, site.model);
    const double ta = test.alignment_average_s;
    for (int j = 0; j < 6; ++j) {
      const double pulse = j < 3 ? test.torquer_pulse_rad : test.dv_pulse_mps;
      counting.push_back(add_column(-1, 2.0 * pulse * pulse / 12.0 / (ta * ta)));
    }
  }

  for (std::size_t m = 0; m < rows.size(); ++m) {
    const auto i = static_cast<Eigen::Index>(rows[m]);
    const int a = layout.rows[rows[m]].axis;
    const ExtendedMap& e = maps.position[m];
    s.replaced[rows[m]] = true;
    s.x_columns.row(i) = e.row(a).leftCols<uncertainty_slot::kDim>();
    for (std::size_t j = 0; j < fresh.size(); ++j) extra[fresh[j]][i] = e(a, kRealignedSlots[j].z_index);
    if (uses_test_run(scheme)) {
      s.estimate_map.row(i) = e.row(a).segment<kEstimateCount>(z_slot::kU2);
      for (int b = 0; b < 3; ++b) {
        const double coefficient = e(a, z_slot::kU2 + b) * per_r0[1] + e(a, z_slot::kU3 + b) * per_r0[2];
        s.x_columns.row(i) -= coefficient * r0_map.row(b);
        if (!rounding.empty()) extra[rounding[static_cast<std::size_t>(b)]][i] = -coefficient;
      }
    }
    if (uses_alignment_data(scheme)) {
      const Eigen::Matrix<double, 1, 6> effect = e.row(a).segment<6>(z_slot::kTorquerCommands);
      s.x_columns.row(i) += effect * measured;
      for (int j = 0; j < 6; ++j) extra[counting[static_cast<std::size_t>(j)]][i] = effect[j];
    }
  }
  s.columns.resize(n, static_cast<Eigen::Index>(extra.size()));
  for (std::size_t j = 0; j < extra.size(); ++j) s.columns.col(static_cast<Eigen::Index>(j)) = extra[j];
  return s;
}

std::optional<SchemeEstimates> record_estimates(const RecordRun& run, const RecordSite& site,
                                                const TestRunEstimators& estimators) {
  const double tau = site.filter_interval_s;
  const int K = record_test_options(site).intervals();
  Eigen::MatrixXd accel(K, 3), position(K, 3);
  std::vector<bool> seen(static_cast<std::size_t>(K), false);
  for (const RecordRow& row : run.rows) {
    if (row.phase != Phase::kTest) continue;
    const double k = row.t_s / tau;
    const auto kk = static_cast<int>(std::lround(k));
    if (kk < 1 || kk > K || std::abs(k - kk) > 1e-6 || !row.r_ap_m) continue;
    for (int a = 0; a < 3; ++a) {
      if (!row.f_mps2[a]) return std::nullopt;
      accel(kk - 1, a) = *row.f_mps2[a];
      position(kk - 1, a) = (*row.r_ap_m)[a];
    }
    seen[static_cast<std::size_t>(kk - 1)] = true;
  }
  for (bool s : seen)
    if (!s) return std::nullopt;
  const Eigen::Matrix<double, kEstimateRows, 3> e =
      apply_estimators<3>(estimators, site.model, site.test_duration_s, position, accel);
  SchemeEstimates u;
  for (int a = 0; a < 3; ++a) {
    u[a] = e(kU2Row, a);
    u[3 + a] = e(kU3Row, a);
    u[6 + a] = e(kU3AccelRow, a);
    u[9 + a] = e(kDfAtTestEndRow, a);
  }
  return u;
}

}  // namespace insmc::runs
