// The linear-Gaussian run model (montecarlo/records/runs/model): responses against
// closed forms and against the linear model's own columns, the analyser's
// expected squares against draws from the model, the metric, the candidates
// and the extraction of records other software may write.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <tuple>

#include "lib/truth/simulator.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "lib/units/units.h"
#include "montecarlo/records/runs/model/gaussian_model.h"
#include "montecarlo/records/runs/model/pulse_counting.h"
#include "montecarlo/records/runs/model/response.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::runs {
namespace {

RecordSite site() { return testing::test_site(); }

Layout layout(double end_s) { return testing::test_layout(end_s); }

TEST(GapResponse, ConstantAccelerometerErrorGivesTheSchulerClosedForm) {
  const Layout l = layout(3000.0);
  const RecordSite s = site();
  InputSignal in;
  in.columns = 1;
  in.at = [](double, runs::Columns3& a, runs::Columns3& th) {
    a.setZero();
    th.setZero();
    a(0, 0) = 1.0;
  };
  const Eigen::MatrixXd r = input_response(l, s, in);
  const double ws = s.model.schuler_radps();
  for (std::size_t i = 0; i < l.rows.size(); ++i) {
    const ObservationRow& row = l.rows[i];
    const double want = row.axis != 0 ? 0.0
                        : row.quantity == Quantity::kF ? 1.0
                                                       : (1.0 - std::cos(ws * row.t_s)) / (ws * ws);  // (3.24)
    EXPECT_NEAR(r(static_cast<Eigen::Index>(i), 0), want, 1e-9 * (1.0 + std::abs(want))) << row.t_s;
  }
}

TEST(GapResponse, AnAccelerometerInputEqualsTheLinearModelsSwitchOverBiasColumn) {
  // ∂f_cx enters the linear model (3.18) as a pure navigation-mode bias: the
  // input path (response.h) must reproduce LinearErrorModel's column.
  const Layout l = layout(6300.0);
  const RecordSite s = site();
  const Eigen::MatrixXd x = uncertainty_response(l, s);
  for (int k = 0; k < 2; ++k) {
    InputSignal in;
    in.columns = 1;
    in.at = [k](double, runs::Columns3& a, runs::Columns3& th) {
      a.setZero();
      th.setZero();
      a(k, 0) = 1.0;
    };
    const Eigen::MatrixXd r = input_response(l, s, in);
    const Eigen::VectorXd col = x.col(uncertainty_slot::kBiasChangeConst + k);
    EXPECT_LT((r.col(0) - col).cwiseAbs().maxCoeff(), 1e-9 * col.cwiseAbs().maxCoeff()) << k;
  }
}

TEST(GapResponse, APlatformTiltIsSeenAsGravityAcrossTheAccelerometers) {
  // f^a = (I − [θ×]) f^{a'} with f^{a'} = (0, 0, −g) at t = 0: a tilt θ_y gives
  // f_x = g θ_y and a tilt θ_x gives f_y = −g θ_x.
  const Layout l = layout(60.0);
  const RecordSite s = site();
  InputSignal in;
  in.columns = 2;
  in.at = [](double, runs::Columns3& a, runs::Columns3& th) {
    a.setZero();
    th.setZero();
    th(1, 0) = 1.0;
    th(0, 1) = 1.0;
  };
  const Eigen::MatrixXd r = input_response(l, s, in);
  const double g = s.model.gravity_mps2;
  ASSERT_EQ(l.rows[0].quantity, Quantity::kF);
  EXPECT_NEAR(r(0, 0), g, 1e-3 * g);   // f_x at t = 10 s, θ_y
  EXPECT_NEAR(r(1, 1), -g, 1e-3 * g);  // f_y, θ_x
}

/// Per-run group sums of `runs` draws y = H c + e, c from the model's priors
/// and e with the variances `noise_var`.
std::vector<GroupSums> sums_of_draws(const GaussianModel& m, const RunAnalyser& a, const Eigen::VectorXd& noise_var,
                                     std::uint64_t seed, int runs = 400) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  std::vector<GroupSums> out;
  for (int r = 0; r < runs; ++r) {
    Eigen::VectorXd c(m.prior_var.size()), e(noise_var.size());
    for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = std::sqrt(m.prior_var[j]) * n01(rng);
    for (Eigen::Index i = 0; i < e.size(); ++i) e[i] = std::sqrt(noise_var[i]) * n01(rng);
    out.push_back(a.analyse(m.H * c + e));
  }
  return out;
}

/// Per group, the mean over runs of the mean z² against want(g), within 4.5
/// standard errors of the per-run means (independent across runs; a false
/// failure ~7e-6 per group). Returns the groups checked.
template <class Want>
int expect_group_means(const std::vector<GroupSums>& runs, const Want& want) {
  int checked = 0;
  for (int g = 0; g < kGroupCount; ++g) {
    if (!(runs.front().count[g] > 0)) continue;
    double sum = 0, sq = 0;
    for (const GroupSums& r : runs) {
      const double v = r.z2[g] / r.count[g];
      sum += v, sq += v * v;
    }
    const auto n = static_cast<double>(runs.size());
    const double mean = sum / n, sd = std::sqrt((sq - n * mean * mean) / (n - 1));
    EXPECT_LT(std::abs(mean - want(g)), 4.5 * sd / std::sqrt(n)) << group_name(g) << " mean " << mean << " want " << want(g);
    ++checked;
  }
  return checked;
}

TEST(GapAnalysis, NormalizedSquaresAverageOneOnDataDrawnFromTheModel) {
  // E z² = 1 per group for data y = H c + e drawn with the model's own second moments.
  const Layout l = layout(3600.0);
  const RecordSite s = site();
  const GaussianModel m = combine(make_base_model(l, s, UncertaintyModel{}.variance()), {});
  const RunAnalyser a(l, m);
  EXPECT_GT(expect_group_means(sums_of_draws(m, a, m.noise_var, 7), [](int) { return 1.0; }), 0);
}

TEST(GapAnalysis, ActualSquaresAverageWhatDrawsWithTheActualNoiseGive) {
  // The fit weights rows with the model-error floor; data drawn with only
  // the actual noise (position resolution, counting) must average the
  // expected squares E_i/e_i of run_analysis.h, group by group.
  const Layout l = layout(3600.0);
  RecordSite s = site();
  s.position_resolution_m = 3 * kFtToM;
  const GaussianModel m = combine(make_base_model(l, s, UncertaintyModel{}.variance()), {});
  const RunAnalyser a(l, m);
  const std::vector<GroupSums> runs = sums_of_draws(m, a, m.actual_noise_var, 11);
  const GroupSums& one = runs.front();  // E/e depends on the layout only
  expect_group_means(runs, [&](int g) { return one.expected[g] / one.count[g]; });
  // Groups where the floor, not the data, sets the normalizer: the check is
  // not the trivial E = e there (the test-run r groups at least).
  int floored = 0;
  for (int g = 0; g < kGroupCount; ++g) floored += one.count[g] > 0 && one.expected[g] < 0.5 * one.count[g];
  EXPECT_GE(floored, 3);
}

TEST(GapLayout, ARunThatStoppedEarlyBeginsTheLongerLayout) {
  const Layout longer = layout(3600.0), shorter = layout(1800.0);
  EXPECT_EQ(rows_begun(shorter, longer), shorter.rows.size());  // its last r row (t = 1800 s) is in both
  // A run that stopped at 1830 s keeps the r row at 1830 s that the longer
  // layout (r rows each 60 s) has not: all but that row begin it.
  Layout stopped = layout(1830.0);
  for (int k = 0; k < 3; ++k) stopped.rows.push_back({1830.0, Quantity::kR, k, stopped.rows.back().group});
  EXPECT_EQ(rows_begun(stopped, longer), stopped.rows.size() - 3);
  Layout other_test = shorter;
  other_test.test_rows -= 3;
  EXPECT_EQ(rows_begun(other_test, longer), 0U);
  EXPECT_EQ(rows_begun(longer, shorter), 0U);
}

TEST(GapAnalysis, ARunThatStoppedEarlyGetsTheSumsOfItsOwnLayout) {
  // The diagnosis analyses a shortened run under the longer layout it
  // begins (one analyser for both); its sums must be those of its own
  // layout's model, built from scratch.
  const Layout longer = layout(3600.0), shorter = layout(1800.0);
  // Continuous f: pulse counting's integration steps follow a layout's
  // length (pulse_counting.h), and would differ by their round-off alone.
  RecordSite s = site();
  s.dv_pulse_mps = 0.0;
  const UncertaintyVector x_var = UncertaintyModel{}.variance();
  const GaussianModel m_longer = combine(make_base_model(longer, s, x_var), {});
  const GaussianModel m_shorter = combine(make_base_model(shorter, s, x_var), {});
  const auto n = static_cast<Eigen::Index>(shorter.rows.size());
  const GaussianModel m_first = first_rows(m_longer, n);
  EXPECT_LT((m_first.H - m_shorter.H).cwiseAbs().maxCoeff(), 1e-9 * m_shorter.H.cwiseAbs().maxCoeff());
  const RunAnalyser shared(longer, m_longer), own(shorter, m_shorter);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n01;
  for (int draw = 0; draw < 3; ++draw) {
    Eigen::VectorXd c(m_shorter.prior_var.size()), e(n);
    for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = std::sqrt(m_shorter.prior_var[j]) * n01(rng);
    for (Eigen::Index i = 0; i < n; ++i) e[i] = std::sqrt(m_shorter.noise_var[i]) * n01(rng);
    const Eigen::VectorXd y = m_shorter.H * c + e;
    const GroupSums a = shared.analyse(y), b = own.analyse(y);
    for (int g = 0; g < kGroupCount; ++g) {
      EXPECT_EQ(a.count[g], b.count[g]) << group_name(g);
      EXPECT_NEAR(a.z2[g], b.z2[g], 1e-7 * (1.0 + b.z2[g])) << group_name(g);
      EXPECT_NEAR(a.expected[g], b.expected[g], 1e-7 * (1.0 + b.expected[g])) << group_name(g);
    }
  }
}

TEST(GapModel, ACandidateWideningThePriorsKeepsTheFloorTheNullWasCalibratedOn) {
  // The floor's relative part follows the base model's priors (what
  // --bound sets and the null is simulated with), not a candidate's: the
  // null's κ and λ are shares of that floor.
  const Layout l = layout(3600.0);
  const RecordSite s = site();
  const UncertaintyVector table = UncertaintyModel{}.variance();
  const BaseModel base = make_base_model(l, s, table);
  Extension wider;
  wider.x_var_scale.setConstant(100.0);
  const GaussianModel m = combine(base, {&wider});
  EXPECT_EQ(m.prior_var.head(uncertainty_slot::kDim), 100.0 * table);
  const GaussianModel plain = combine(base, {});
  EXPECT_EQ(m.noise_var, plain.noise_var);
  // A base of wider priors has a wider floor on the r rows, none on f.
  const BaseModel widened = make_base_model(l, s, 100.0 * table);
  int wider_rows = 0;
  for (std::size_t i = 0; i < l.rows.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (l.rows[i].quantity == Quantity::kR) {
      EXPECT_GT(widened.noise_var[k], base.noise_var[k]) << l.rows[i].t_s;
      ++wider_rows;
    } else {
      EXPECT_EQ(widened.noise_var[k], base.noise_var[k]) << l.rows[i].t_s;
    }
  }
  EXPECT_GT(wider_rows, 0);
}

TEST(GapPulseCounting, TheSawtoothIntegralIsExact) {
  // ∫ e dt over a step on which V is linear, against a fine midpoint sum.
  const double w = 0.3;
  for (const auto& [v0, v1, phase] : {std::tuple{0.0, 0.05, 0.2}, std::tuple{-0.4, 2.7, -0.45},
                                      std::tuple{5.0, 4.1, 0.0}, std::tuple{1.0, 1.0, 0.3}}) {
    const double h = 5.0;
    constexpr int kSteps = 200000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
      const double u = (i + 0.5) / kSteps;
      sum += counting_velocity_error(v0 + u * (v1 - v0), phase, w) * h / kSteps;
    }
    // The midpoint sum errs by at most a pulse over one sub-step at each of
    // the |Δv|/w + 1 jumps of the sawtooth.
    const double jumps = std::abs(v1 - v0) / w + 1.0;
    EXPECT_NEAR(counting_velocity_error_integral(v0, v1, h, phase, w), sum, jumps * w * h / kSteps) << v0 << " " << v1;
  }
  EXPECT_DOUBLE_EQ(counting_velocity_error(0.0, 0.37, w), 0.0);  // no pulse, no error
}

TEST(GapPulseCounting, PositionScatterMatchesTheTruthSimulatorsCounters) {
  // Truth runs with pulses of w less the same runs with a continuous output
  // isolate what the counters do to r: on x an offset that switches on
  // minutes into the run, on y and z at once. Their variance per axis and
  // window against the model's (columns² + rest), as a log ratio; bound 4.5
  // standard errors of the log of two variance estimates from N truth runs
  // and the model's 256 draws, sqrt(2/N + 2/256).
  Layout l;
  for (double t = 30.0; t <= 2700.0; t += 30.0)
    for (int k = 0; k < 3; ++k) l.rows.push_back({t, Quantity::kR, k, group_of(Stage::kTest, Quantity::kR, k, 0)});
  l.test_rows = static_cast<int>(l.rows.size());
  RecordSite s = site();
  const double w = 0.5;
  s.dv_pulse_mps = w;
  const UncertaintyModel prior;
  const PulseCounting pc =
      pulse_counting(l, s, w, prior.variance(), Eigen::VectorXd::Ones(static_cast<Eigen::Index>(l.rows.size())));
  const Eigen::VectorXd model = pc.columns.rowwise().squaredNorm() + pc.noise_var;
  TruthOptions o;
  o.model = s.model;
  o.system = s.system;
  std::vector<double> times;
  for (double t = 30.0; t <= 2700.0; t += 30.0) times.push_back(t);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  constexpr int kRuns = 300;
  Eigen::VectorXd truth = Eigen::VectorXd::Zero(model.size());
  for (int r = 0; r < kRuns; ++r) {
    UncertaintyVector x;  // uniform with the priors' variance
    for (int j = 0; j < uncertainty_slot::kDim; ++j) x[j] = std::sqrt(3.0 * prior.variance()[j]) * (2.0 * u01(rng) - 1.0);
    TruthOptions pulsed = o, continuous = o;
    pulsed.dv_pulse_mps = w;
    for (int k = 0; k < 3; ++k) pulsed.pulse_phase[k] = u01(rng) - 0.5;
    continuous.dv_pulse_mps = 0.0;
    const TruthRun a = simulate_truth(pulsed, x, times), b = simulate_truth(continuous, x, times);
    for (std::size_t i = 0; i < l.rows.size(); ++i) {
      const auto k = static_cast<std::size_t>(i / 3);
      const double d = a.position_error_ap_m[k][l.rows[i].axis] - b.position_error_ap_m[k][l.rows[i].axis];
      truth[static_cast<Eigen::Index>(i)] += d * d / kRuns;
    }
  }
  const double bound = 4.5 * std::sqrt(2.0 / kRuns + 2.0 / 256.0);
  for (int axis = 0; axis < 3; ++axis) {
    for (const auto& [from, to] : {std::pair{30.0, 600.0}, std::pair{600.0, 1200.0}, std::pair{1200.0, 2700.0}}) {
      double m = 0, t = 0;
      for (std::size_t i = 0; i < l.rows.size(); ++i)
        if (l.rows[i].axis == axis && l.rows[i].t_s >= from && l.rows[i].t_s <= to)
          m += model[static_cast<Eigen::Index>(i)], t += truth[static_cast<Eigen::Index>(i)];
      std::printf("counting axis %d %4.0f-%4.0f s: model/truth %.3f\n", axis, from, to, m / t);
      EXPECT_LT(std::abs(std::log(m / t)), bound) << "axis " << axis << " " << from << "-" << to << " s: model " << m
                                                  << " truth " << t;
    }
  }
}

TEST(GapLayout, RecordsOfOtherSoftwareAreTakenAsTheyCome) {
  // f every 5 s (windows of 10 s overlap: every other is kept), an f gap,
  // r every 20 s, a run that stops early, arbitrary run numbers.
  RecordFile file;
  file.header = RecordHeader::make(45.0, System::kTheodolite, 900.0, Scheme::kNone);
  for (std::int64_t id : {17, -3}) {
    RecordRun run;
    run.id = id;
    const double end = id == 17 ? 6300.0 : 2000.0;
    for (double t = 5.0; t <= end; t += 5.0) {
      RecordRow row;
      row.run = id;
      row.t_s = t;
      row.phase = t <= 900.0 ? Phase::kTest : Phase::kNav;
      if (!(t > 300.0 && t < 400.0)) row.f_mps2 = {1e-4, 2e-4, 3e-4};
      row.r_ap_m = std::fmod(t, 20.0) == 0.0 ? OptionalVector3(Eigen::Vector3d(1.0, 2.0, 3.0)) : OptionalVector3();
      if (row.r_ap_m || row.has_f()) run.rows.push_back(row);
    }
    file.runs.push_back(run);
  }
  EXPECT_DOUBLE_EQ(median_f_spacing(file), 5.0);
  {
    // Navigation f of another writer's sampling (every 10 s, outnumbering
    // the test's 5 s rows) does not set the test run's filter interval.
    RecordFile sparse = file;
    for (RecordRun& run : sparse.runs)
      for (RecordRow& row : run.rows)
        if (row.phase == Phase::kNav && std::fmod(row.t_s, 10.0) != 0.0) row.f_mps2 = {};
    EXPECT_DOUBLE_EQ(median_f_spacing(sparse), 5.0);
  }
  RecordSite s = site();
  const std::vector<RunData> runs = extract_runs(file, s);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].id, 17);
  for (const RunData& r : runs) {
    // r rows: one per slot of r_spacing_s (30 s in the test run, 60 s after
    // it) counted from the first r row, so a record one run lacks moves one
    // row and not every row after it (extract_runs); the last always counts.
    double last_f = -1e9, first_r = -1.0, last_slot = -1.0;
    for (const ObservationRow& row : r.layout.rows) {
      if (row.axis != 0) continue;
      if (row.quantity == Quantity::kF) {
        EXPECT_GE(row.t_s - last_f, 10.0 - 1e-9);
        EXPECT_FALSE(row.t_s > 300.0 && row.t_s < 400.0);
        last_f = row.t_s;
      } else if (row.t_s <= 900.0) {
        if (first_r < 0) first_r = row.t_s;
        const double slot = std::floor((row.t_s - first_r) / 30.0 + 1e-9);
        EXPECT_TRUE(slot > last_slot || row.t_s == r.end_s) << row.t_s;
        last_slot = slot;
      }
    }
    EXPECT_EQ(r.values.size(), r.layout.rows.size());
  }
  EXPECT_DOUBLE_EQ(runs[1].end_s, 2000.0);
}

}  // namespace
}  // namespace insmc::runs
