#include "montecarlo/records/compensate/unit_prediction.h"

#include <Eigen/Cholesky>
#include <boost/math/distributions/chi_squared.hpp>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lib/common/assert.h"
#include "lib/compensation/schemes/scheme_definition.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"
#include "lib/propagation/position_maps.h"
#include "lib/uncertainty/catalogue.h"
#include "montecarlo/records/runs/model/gaussian_model.h"
#include "montecarlo/records/runs/model/scheme_rows.h"

namespace insmc::compensate {
namespace {

/// The causes' prior mean: x's from the uncertainty model, a realignment's
/// fresh draw that of its x slot, everything else 0.
Eigen::VectorXd cause_prior_mean(const runs::BaseModel& base, const runs::GaussianModel& model,
                                 const UncertaintyVector& x_mean) {
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(model.H.cols());
  mu.head(uncertainty_slot::kDim) = x_mean;
  const Eigen::Index first_scheme = uncertainty_slot::kDim + base.counting.columns.cols();
  for (std::size_t j = 0; j < base.scheme_x_index.size(); ++j)
    if (base.scheme_x_index[j] >= 0) mu[first_scheme + static_cast<Eigen::Index>(j)] = x_mean[base.scheme_x_index[j]];
  return mu;
}

/// The f rows' pulse counting as it is: a window's count error is
/// (e_k − e_{k−1})/τ, e_k the counter's remainder at t_k (uniform, w²/12
/// each; e_0 stands for the pulse phase ρ0 w at switch-over, which the
/// counted velocity carries from the first pulse on: e_k = ρ0 w + a rounding
/// for k ≥ 1 has the same differences), so neighbouring windows are
/// anti-correlated and a sum over windows telescopes, which the fits of
/// (4.4), (5.10) rely on. The gap's model
/// takes the windows independent (w²/(6τ²) each; runs/model/pulse_counting.h),
/// which would overstate the spread of Δf̂(T) (5.3 at 84 min: 5,632 m for
/// the population instead of 5,136 m, `insmc run` 5,111 m). Appends the
/// remainders as causes and takes their share off the rows' noise.
void count_f_remainders(runs::GaussianModel& model, const runs::Layout& layout, double pulse_mps, double tau_s) {
  if (!(pulse_mps > 0)) return;
  int K = 0;
  for (const runs::ObservationRow& row : layout.rows) K = std::max(K, static_cast<int>(std::lround(row.t_s / tau_s)));
  const Eigen::Index first = model.H.cols(), added = 3 * (K + 1);  // e_0..e_K
  model.H.conservativeResize(Eigen::NoChange, first + added);
  model.H.rightCols(added).setZero();
  model.prior_var.conservativeResize(first + added);
  model.prior_var.tail(added).setConstant(pulse_mps * pulse_mps / 12.0);
  const double window_var = pulse_mps * pulse_mps / (6.0 * tau_s * tau_s);
  for (std::size_t i = 0; i < layout.rows.size(); ++i) {
    const runs::ObservationRow& row = layout.rows[i];
    if (row.quantity != runs::Quantity::kF) continue;
    const auto r = static_cast<Eigen::Index>(i);
    const Eigen::Index k = std::lround(row.t_s / tau_s);
    model.H(r, first + 3 * k + row.axis) = 1.0 / tau_s;
    model.H(r, first + 3 * (k - 1) + row.axis) = -1.0 / tau_s;
    model.noise_var[r] = std::max(model.noise_var[r] - window_var, 0.0);
    model.actual_noise_var[r] = std::max(model.actual_noise_var[r] - window_var, 0.0);
  }
}

/// The linear estimate's gain on the test rows and its error covariance,
/// the rows' noise W taken with the model-error floor (the linear level's
/// allowance against the truth, docs/gap-method.md): (I − GH) P (I − GH)ᵀ + G W Gᵀ.
struct LinearGain {
  Eigen::MatrixXd G, error_covariance;
  Eigen::LLT<Eigen::MatrixXd> S;  ///< of the rows' covariance H P Hᵀ + W
};
LinearGain linear_gain(const runs::GaussianModel& model) {
  const Eigen::MatrixXd& H = model.H;
  const Eigen::VectorXd& p = model.prior_var;
  const Eigen::MatrixXd PHt = p.asDiagonal() * H.transpose();
  Eigen::MatrixXd S = H * PHt;
  S.diagonal() += model.noise_var;
  LinearGain g;
  g.S.compute(S);
  INSMC_ASSERT(g.S.info() == Eigen::Success, "test-row covariance not positive definite ({} rows)", H.rows());
  g.G = g.S.solve(PHt.transpose()).transpose();  // P Hᵀ S⁻¹
  Eigen::MatrixXd M = -g.G * H;
  M.diagonal().array() += 1.0;
  g.error_covariance = M * p.asDiagonal() * M.transpose() + g.G * model.noise_var.asDiagonal() * g.G.transpose();
  return g;
}

runs::RecordSite site_for(const UnitRecords& records, Scheme scheme, double realignment_duration_s) {
  runs::RecordSite site = records.site;
  site.scheme = scheme;
  const double T = site.test_duration_s;
  site.nav_start_s = realigns(scheme) ? T + realignment_duration_s : resets_at_test_end(scheme) ? T : 0.0;
  return site;
}

/// SchemeEstimates order (scheme_rows.h).
runs::SchemeEstimates estimate_vector(const TestRunEstimates& e) {
  runs::SchemeEstimates u;
  u << e.u2, e.u3, e.u3_accel, e.df_at_test_end_mps2;
  return u;
}

SchemeCompensation compensation_of(Scheme scheme, const UnitRecords& records, const TestRunEstimates& estimates) {
  SchemeCompensation c;
  c.resets_at_test_end = resets_at_test_end(scheme);
  c.realigns = realigns(scheme);
  c.from_alignment_data = uses_alignment_data(scheme);
  const SchemeDefinition& d = scheme.definition();
  if (d.truth_action == nullptr || c.from_alignment_data) return c;
  const TruthSchemeContext context{records.site.system, records.site.model, records.site.test_duration_s, estimates};
  TruthOptions o;
  UncertaintyVector change = UncertaintyVector::Zero();
  d.truth_action(context, o, change);
  c.step_mps2 = o.accel_compensation.step_mps2;
  c.ramp_mps3 = o.accel_compensation.ramp_mps3;
  c.torquer_radps = change.segment<3>(uncertainty_slot::kGyroDrift);  // rates that act as a drift change (5.5)
  return c;
}

}  // namespace

/// ConsistencyBand: S_a = S − D, D the floor's share of the rows' noise,
/// so S⁻¹S_a = I − S⁻¹D: tr = n − Σ dᵢ (S⁻¹)ᵢᵢ and
/// tr((S⁻¹S_a)²) = n − 2 Σ dᵢ (S⁻¹)ᵢᵢ + Σᵢⱼ dᵢ dⱼ ((S⁻¹)ᵢⱼ)².
ConsistencyBand consistency_band(const runs::GaussianModel& model, const Eigen::LLT<Eigen::MatrixXd>& S) {
  const Eigen::Index n = model.H.rows();
  const Eigen::VectorXd d = (model.noise_var - model.actual_noise_var).cwiseMax(0.0);
  const Eigen::MatrixXd S_inv = S.solve(Eigen::MatrixXd::Identity(n, n));
  const double dS = d.dot(S_inv.diagonal());
  const double dSd = d.dot(S_inv.cwiseAbs2() * d);
  ConsistencyBand band;
  band.linear_mean = static_cast<double>(n) - dS;
  band.linear_sd = std::sqrt(std::max(0.0, 2.0 * (static_cast<double>(n) - 2.0 * dS + dSd)));
  return band;
}

double ConsistencyBand::linear_p(double chi2) const {
  if (!(linear_mean > 0 && linear_sd > 0)) return 1.0;
  const double c = linear_sd * linear_sd / (2.0 * linear_mean);
  const double nu = 2.0 * linear_mean * linear_mean / (linear_sd * linear_sd);
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(nu), std::max(chi2, 0.0) / c));
}

double UnitPositionError::unit_rms_m(int a) const { return std::sqrt(mean_m[a] * mean_m[a] + covariance_m2(a, a)); }
double UnitPositionError::population_rms_m(int a) const { return std::sqrt(population_m2(a, a)); }
double UnitPositionError::unit_horizontal_rms_m() const {
  return std::sqrt(horizontal_mean_m().squaredNorm() + horizontal_covariance_m2().trace());
}
double UnitPositionError::population_horizontal_rms_m() const {
  return std::sqrt((horizontal * population_m2 * horizontal.transpose()).trace());
}

namespace {

/// B: the report's estimates (SchemeEstimates order: Û2, Û3, Û3 from f,
/// Δf̂(T), per axis) as a linear map of a unit's test rows.
Eigen::MatrixXd estimates_of_test_rows(const UnitRecords& records, const runs::Layout& layout) {
  const runs::RecordSite& site = records.site;
  const double tau = site.filter_interval_s, T = site.test_duration_s;
  const auto K = static_cast<Eigen::Index>(runs::record_test_options(site).intervals());
  const auto n = static_cast<Eigen::Index>(layout.rows.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(runs::kEstimateCount, n);
  const TestRunEstimators estimators = layout_estimators(site, layout);
  for (int a = 0; a < 3; ++a) {
    Eigen::MatrixXd position = Eigen::MatrixXd::Zero(K, n), accel = Eigen::MatrixXd::Zero(K, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const runs::ObservationRow& row = layout.rows[static_cast<std::size_t>(i)];
      if (row.axis != a) continue;
      const Eigen::Index k = std::lround(row.t_s / tau);
      INSMC_ASSERT(k >= 1 && k <= K, "test row at {} s off the filter grid", row.t_s);
      (row.quantity == runs::Quantity::kF ? accel : position)(k - 1, i) = 1.0;
    }
    const Eigen::MatrixXd e = apply_estimators(estimators, site.model, T, position, accel);
    B.row(a) = e.row(kU2Row);
    B.row(3 + a) = e.row(kU3Row);
    B.row(6 + a) = e.row(kU3AccelRow);
    B.row(9 + a) = e.row(kDfAtTestEndRow);
  }
  return B;
}

}  // namespace

std::vector<Identifiability> identifiability(const UnitRecords& records, const UncertaintyModel& prior) {
  const ShortRunMatrices paper = paper_short_run_matrices(records.site.system, records.site.model);
  const Sensitivity3* maps[] = {&paper.u2, &paper.u3, &paper.u4};
  const char* names[] = {"U2", "U3", "U4"};
  const UncertaintyVector x_var = prior.variance();
  std::vector<Identifiability> out;
  for (int q = 0; q < 3; ++q)
    for (int a = 0; a < 3; ++a) {
      Identifiability e;
      e.name = fmt::format("{}_{}", names[q], "xyz"[a]);
      const Eigen::RowVectorXd l = maps[q]->row(a);
      const Eigen::ArrayXd share = l.array().square().transpose() * x_var.array();
      e.prior_sigma = std::sqrt(share.sum());
      std::vector<int> order(uncertainty_slot::kDim);
      for (int j = 0; j < uncertainty_slot::kDim; ++j) order[static_cast<std::size_t>(j)] = j;
      std::sort(order.begin(), order.end(), [&](int i, int j) { return share[i] > share[j]; });
      for (int k = 0; k < 3 && share[order[static_cast<std::size_t>(k)]] > 0.01 * share.sum(); ++k)
        e.mixes.emplace_back(std::string(catalogue()[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])].name),
                             share[order[static_cast<std::size_t>(k)]] / share.sum());
      out.push_back(e);
    }
  // The estimates' sigma for test runs of T, 2T and 4T, as many filter
  // windows each (τ scaled: the fits hardly depend on it, the model's size
  // stays that of the records').
  for (const double factor : {1.0, 2.0, 4.0}) {
    runs::RecordSite site = site_for(records, Scheme::kNone, 0.0);
    site.test_duration_s *= factor;
    site.filter_interval_s *= factor;
    const int K = runs::record_test_options(site).intervals();
    const runs::Layout layout = test_run_layout(K, site.filter_interval_s);
    const runs::BaseModel base = runs::make_base_model(layout, site, x_var);
    runs::GaussianModel model = runs::combine(base, {});
    count_f_remainders(model, layout, site.dv_pulse_mps, site.filter_interval_s);
    const Eigen::MatrixXd error = linear_gain(model).error_covariance.topLeftCorner(uncertainty_slot::kDim, uncertainty_slot::kDim);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Eigen::RowVectorXd l = maps[i / 3]->row(static_cast<Eigen::Index>(i % 3));
      out[i].sigma_by_duration.emplace_back(site.test_duration_s,
                                            std::sqrt(std::max(0.0, (l * error * l.transpose())(0, 0))));
    }
  }
  return out;
}

UnitConditioning unit_conditioning(const UnitRecords& records, const runs::Layout& layout, const UncertaintyModel& prior) {
  const runs::RecordSite site = site_for(records, Scheme::kNone, 0.0);
  const runs::BaseModel base = runs::make_base_model(layout, site, prior.variance());
  UnitConditioning u;
  u.layout = layout;
  u.model = runs::combine(base, {});
  count_f_remainders(u.model, layout, site.dv_pulse_mps, site.filter_interval_s);
  LinearGain gain = linear_gain(u.model);
  u.gain = std::move(gain.G);
  u.error_covariance = std::move(gain.error_covariance);
  u.row_covariance = std::move(gain.S);
  u.cause_mean = cause_prior_mean(base, u.model, prior.mean());
  u.estimates_map = estimates_of_test_rows(records, layout);
  u.consistency_band = consistency_band(u.model, u.row_covariance);
  return u;
}

UnitPosterior condition_unit(const UnitRecords& records, const UnitTestRun& run, const UncertaintyModel& prior) {
  return condition_unit(records, run, unit_conditioning(records, run.layout, prior));
}

UnitPosterior condition_unit(const UnitRecords& records, const UnitTestRun& run, const UnitConditioning& shared) {
  INSMC_ASSERT(run.layout == shared.layout, "run {} conditioned on another layout", run.id);
  const runs::RecordSite site = site_for(records, Scheme::kNone, 0.0);
  UnitPosterior c;
  c.model = shared.model;
  c.cause_mean = shared.cause_mean;
  const Eigen::VectorXd innovation = run.values - c.model.mean - c.model.H * c.cause_mean;
  c.cause_estimate = c.cause_mean + shared.gain * innovation;
  c.error_covariance = shared.error_covariance;
  c.consistency_chi2 = innovation.dot(shared.row_covariance.solve(innovation));
  c.consistency_dof = static_cast<int>(innovation.size());
  c.consistency_p = boost::math::cdf(
      boost::math::complement(boost::math::chi_squared(c.consistency_dof), std::max(c.consistency_chi2, 0.0)));
  c.consistency_band = shared.consistency_band;
  c.estimates_map = shared.estimates_map;
  const TestRunEstimators& est = run.estimators;
  const Eigen::Vector4d per_r0 = est.position * Eigen::VectorXd::Ones(est.position.cols());
  const Vec3 r0 = LinearErrorModel(site.system, site.model).initial_position() * c.cause_estimate.head(uncertainty_slot::kDim);
  c.crew_estimates = run.estimates;
  c.crew_estimates.u2 -= per_r0[1] * r0;
  c.crew_estimates.u3 -= per_r0[2] * r0;
  return c;
}

std::vector<UnitEstimate> estimate_unit(const UnitRecords& records, const UnitPosterior& c,
                                        const UncertaintyModel& prior) {
  const runs::RecordSite& site = records.site;
  // What each estimate is of, per unit of x: the report's U2..U4 (3.29b–d)
  // and the accelerometer output error at T (4.2), the forcing of (3.24).
  const ShortRunMatrices paper = paper_short_run_matrices(site.system, site.model);
  const Sensitivity3 df_at_end = LinearErrorModel(site.system, site.model).forcing(site.test_duration_s);
  const TestRunEstimators& est = *site.estimators;
  struct Coefficient {
    const char* name;
    const Sensitivity3* map;
    const char* unit;
    const Vec3* report;
  };
  const TestRunEstimates& crew = c.crew_estimates;
  // Every term of (3.29b-d) is an angle: a tilt, δf/g (a tilt's
  // equivalent), a drift over ω_ie (the angle it turns per earth-rate radian).
  const Coefficient coefficients[] = {{"U2", &paper.u2, "rad", &crew.u2},
                                      {"U3", &paper.u3, "rad", &crew.u3},
                                      {"U4", &paper.u4, "rad", nullptr},
                                      {"df_T", &df_at_end, "m/s^2", &crew.df_at_test_end_mps2}};
  const UncertaintyVector x_var = prior.variance();
  std::vector<UnitEstimate> out;
  for (const Coefficient& q : coefficients)
    for (int a = 0; a < 3; ++a) {
      const Eigen::RowVectorXd l = q.map->row(a);
      UnitEstimate e;
      e.name = fmt::format("{}_{}", q.name, "xyz"[a]);
      e.unit = q.unit;
      e.value = l * c.cause_estimate.head(uncertainty_slot::kDim);
      e.sigma = std::sqrt(std::max(0.0, (l * c.error_covariance.topLeftCorner(uncertainty_slot::kDim, uncertainty_slot::kDim) * l.transpose())(0, 0)));
      e.prior_sigma = std::sqrt((l.array().square() * x_var.transpose().array()).sum());
      const bool fitted = q.report != nullptr && (q.map != &paper.u3 || est.fit_u3);
      if (fitted) e.report_estimator = (*q.report)[a];
      out.push_back(e);
    }
  return out;
}

SchemePrediction predict_scheme(const UnitRecords& records, const UnitTestRun& run, const UnitPosterior& posterior,
                                Scheme scheme, const UncertaintyModel& prior, const std::vector<double>& clock_s,
                                double realignment_duration_s) {
  return predict_scheme(records, run, posterior,
                        scheme_model(records, posterior, scheme, prior, clock_s, realignment_duration_s));
}

SchemeModel scheme_model(const UnitRecords& records, const UnitPosterior& posterior, Scheme scheme,
                         const UncertaintyModel& prior, const std::vector<double>& clock_s,
                         double realignment_duration_s) {
  const runs::RecordSite site = site_for(records, scheme, realignment_duration_s);
  const double T = site.test_duration_s;
  // The navigation after the scheme alone, on the record's clock.
  runs::Layout layout;
  layout.nav = runs::nav_segment_of(scheme);
  layout.nav_start_s = site.nav_start_s;
  const double zero = clock_start_s(scheme, T, site.nav_start_s);
  for (double t : clock_s) {
    INSMC_ASSERT(t > 0, "clock time {} s", t);
    // The report window of the time since T (the gap's groups; not used here).
    const int window = runs::nav_window(layout.nav == runs::NavSegment::kRestart ? t + T : std::max(t + zero, T), T);
    for (int a = 0; a < 3; ++a)
      layout.rows.push_back({t + zero, runs::Quantity::kR, a, runs::group_of(runs::Stage::kNav, runs::Quantity::kR, a, window)});
  }
  const runs::BaseModel base = runs::make_base_model(layout, site, prior.variance());
  const runs::GaussianModel model = runs::combine(base, {});
  const Eigen::VectorXd mu = cause_prior_mean(base, model, prior.mean());
  const Eigen::Index others = model.H.cols() - uncertainty_slot::kDim;
  const Eigen::MatrixXd A_x = model.H.leftCols(uncertainty_slot::kDim), A_o = model.H.rightCols(others);
  const Eigen::VectorXd var_o = model.prior_var.tail(others);
  const Eigen::MatrixXd& E = base.estimate_map;
  // The navigation rows' own counting noise (the position resolution is the
  // readout's, not the position error's).
  const Eigen::VectorXd nav_noise = model.actual_noise_var - base.actual_noise_var;

  SchemeModel m;
  m.scheme = scheme;
  m.clock_s = clock_s;
  m.realignment_duration_s = realignment_duration_s;
  m.position_per_cause = A_x;
  m.position_of_others = A_o * mu.tail(others);
  m.position_per_estimate = E;
  Eigen::MatrixXd unit_cov = A_x * posterior.error_covariance.topLeftCorner(uncertainty_slot::kDim, uncertainty_slot::kDim) * A_x.transpose() +
                             A_o * var_o.asDiagonal() * A_o.transpose();
  unit_cov.diagonal() += nav_noise;
  // The population: the estimates are the estimators applied to random
  // test rows y = H_t c_t + e.
  const runs::GaussianModel& test = posterior.model;
  const Eigen::MatrixXd EB = E * posterior.estimates_map;
  Eigen::MatrixXd via_test = EB * test.H;  // per unit of the test model's causes
  via_test.leftCols(uncertainty_slot::kDim) += A_x;
  const Eigen::VectorXd pop_mean = via_test * posterior.cause_mean + A_o * mu.tail(others);
  Eigen::MatrixXd pop = via_test * test.prior_var.asDiagonal() * via_test.transpose() +
                        EB * test.actual_noise_var.asDiagonal() * EB.transpose() +
                        A_o * var_o.asDiagonal() * A_o.transpose() + pop_mean * pop_mean.transpose();
  pop.diagonal() += nav_noise;
  const double frame_offset = frame_time_offset_s(scheme, T);
  for (std::size_t j = 0; j < clock_s.size(); ++j) {
    const auto r = static_cast<Eigen::Index>(3 * j);
    UnitPositionError p;
    p.t_s = clock_s[j];
    p.covariance_m2 = unit_cov.block<3, 3>(r, r);
    p.population_m2 = pop.block<3, 3>(r, r);
    p.horizontal = local_level_horizontal(frame_offset + clock_s[j], site.model);
    m.envelope.push_back(p);
  }
  return m;
}

SchemePrediction predict_scheme(const UnitRecords& records, const UnitTestRun& run, const UnitPosterior& posterior,
                                const SchemeModel& m) {
  // The unit's own part: its estimate of x and its crew's estimates.
  const Eigen::VectorXd unit_mean = m.position_per_cause * posterior.cause_estimate.head(uncertainty_slot::kDim) +
                                    m.position_of_others + m.position_per_estimate * estimate_vector(run.estimates);
  SchemePrediction out;
  out.scheme = m.scheme;
  out.ready_time_s = ready_time_s(m.scheme, records.site.test_duration_s, m.realignment_duration_s);
  out.compensation = compensation_of(m.scheme, records, posterior.crew_estimates);
  out.envelope = m.envelope;
  for (std::size_t j = 0; j < out.envelope.size(); ++j)
    out.envelope[j].mean_m = unit_mean.segment<3>(static_cast<Eigen::Index>(3 * j));
  return out;
}

}  // namespace insmc::compensate
