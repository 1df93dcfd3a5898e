#include "montecarlo/records/gap/where/estimate_test.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "lib/uncertainty/catalogue.h"
#include "montecarlo/records/gap/null/bootstrap.h"

namespace insmc::gap {
namespace {

/// The prior's reach: a run of the null lies beyond it once in a hundred.
constexpr double kReachQuantile = 0.99;

/// The null runs' summary each statistic is taken against.
struct NullSummary {
  Eigen::VectorXd reach, mean, var;
};

NullSummary summarize(const Eigen::MatrixXd& null) {
  const Eigen::Index J = null.rows();
  NullSummary s{Eigen::VectorXd(J), Eigen::VectorXd(J), Eigen::VectorXd(J)};
  for (Eigen::Index j = 0; j < J; ++j) {
    const Eigen::VectorXd v = null.row(j).transpose();
    std::vector<double> a(static_cast<std::size_t>(v.size()));
    for (Eigen::Index i = 0; i < v.size(); ++i) a[static_cast<std::size_t>(i)] = std::abs(v[i]);
    s.reach[j] = quantile(a, kReachQuantile);
    s.mean[j] = v.mean();
    s.var[j] = std::max((v.array() - s.mean[j]).square().sum() / static_cast<double>(v.size() - 1), 1e-300);
  }
  return s;
}

/// Per estimate: share beyond the reach, spread ratio, |mean| in standard errors (3J values).
Eigen::VectorXd statistics(const Eigen::MatrixXd& z, const std::vector<int>& runs, const NullSummary& s) {
  const Eigen::Index J = z.rows();
  const double m = static_cast<double>(runs.size());
  Eigen::VectorXd t(3 * J);
  for (Eigen::Index j = 0; j < J; ++j) {
    double sum = 0, beyond = 0;
    for (const int r : runs) {
      const double v = z(j, r);
      sum += v;
      beyond += std::abs(v) > s.reach[j];
    }
    const double mean = sum / m;
    double ss = 0;
    for (const int r : runs) ss += (z(j, r) - mean) * (z(j, r) - mean);
    t[3 * j] = beyond / m;
    t[3 * j + 1] = ss / std::max(m - 1.0, 1.0) / s.var[j];
    t[3 * j + 2] = std::abs(mean - s.mean[j]) / std::sqrt(s.var[j] / m);
  }
  return t;
}

/// p of each value of `sorted_null` against itself and of `observed`: the
/// share of null values at least as large, the value counted (p_value_of).
double upper_p(double value, const std::vector<double>& sorted_null) {
  const auto at_least = sorted_null.end() - std::lower_bound(sorted_null.begin(), sorted_null.end(), value);
  return (1.0 + static_cast<double>(at_least)) / (1.0 + static_cast<double>(sorted_null.size()));
}

}  // namespace

RunEstimates run_estimates(const runs::PreparedRuns& p, const std::vector<const runs::RunAnalyser*>& analysers,
                           const ModelNull& null) {
  RunEstimates e;
  // The x columns resolved in every layout a run of the records or the null lies in.
  std::set<int> used(p.layout_of.begin(), p.layout_of.end());
  used.insert(null.layout_of.begin(), null.layout_of.end());
  std::vector<int> common;
  for (int j = 0; j < uncertainty_slot::kDim; ++j) {
    bool everywhere = true;
    for (const int L : used) {
      const std::vector<int>& x = analysers[static_cast<std::size_t>(L)]->estimate_x_columns();
      everywhere = everywhere && std::find(x.begin(), x.end(), j) != x.end();
    }
    if (everywhere) common.push_back(j);
  }
  e.columns = common;
  const auto fill = [&](const std::vector<runs::RunData>& runs, const std::vector<int>& layout_of, Eigen::MatrixXd& out) {
    out.resize(static_cast<Eigen::Index>(common.size()), static_cast<Eigen::Index>(runs.size()));
    tbb::parallel_for(std::size_t{0}, runs.size(), [&](std::size_t r) {
      const runs::RunAnalyser& a = *analysers[static_cast<std::size_t>(layout_of[r])];
      const Eigen::VectorXd y = runs::run_values(runs[r]);
      const Eigen::VectorXd v = a.normalized(y);
      const std::vector<int>& x = a.estimate_x_columns();
      const Eigen::Index rows = v.size() - static_cast<Eigen::Index>(x.size());
      for (std::size_t k = 0; k < common.size(); ++k) {
        const auto at = std::find(x.begin(), x.end(), common[k]) - x.begin();
        out(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(r)) = v[rows + at];
      }
    });
  };
  fill(p.runs, p.layout_of, e.records);
  fill(null.runs, null.layout_of, e.null);
  return e;
}

EstimateTest test_estimates(const RunEstimates& e, const ModelNull& null, const DiagnosisOptions& options,
                            double unmodelled_p) {
  EstimateTest out;
  const auto J = static_cast<Eigen::Index>(e.columns.size());
  const auto n = static_cast<int>(e.records.cols());
  const auto pool_size = static_cast<int>(e.null.cols());
  if (J == 0 || n < 2 || pool_size < 2) {
    out.reason = "no estimate of Table 3.1's x resolved by every run's test rows";
    return out;
  }
  const NullSummary s = summarize(e.null);
  // The null files of G (the same streams: file b is null.unmodelled[b]).
  const auto B = static_cast<std::size_t>(options.bootstrap);
  std::vector<Eigen::VectorXd> boot(B);
  tbb::parallel_for(std::size_t{0}, B, [&](std::size_t b) {
    boot[b] = statistics(e.null, resample(options.seed, static_cast<std::uint64_t>(b), n, pool_size), s);
  });
  const Eigen::Index K = 3 * J;
  std::vector<std::vector<double>> sorted(static_cast<std::size_t>(K), std::vector<double>(B));
  for (Eigen::Index k = 0; k < K; ++k) {
    for (std::size_t b = 0; b < B; ++b) sorted[static_cast<std::size_t>(k)][b] = boot[b][k];
    std::sort(sorted[static_cast<std::size_t>(k)].begin(), sorted[static_cast<std::size_t>(k)].end());
  }
  const Eigen::VectorXd t = statistics(e.records, all_runs(static_cast<std::size_t>(n)), s);
  std::vector<double> p(static_cast<std::size_t>(K));
  for (Eigen::Index k = 0; k < K; ++k) p[static_cast<std::size_t>(k)] = upper_p(t[k], sorted[static_cast<std::size_t>(k)]);
  const auto catalogue_entries = catalogue();
  for (Eigen::Index j = 0; j < J; ++j) {
    EstimateStatistics r;
    r.name = std::string(catalogue_entries[static_cast<std::size_t>(e.columns[static_cast<std::size_t>(j)])].name);
    r.reach = s.reach[j];
    const auto k = static_cast<std::size_t>(3 * j);
    r.beyond = t[3 * j], r.beyond_critical = critical_value(sorted[k], options.alpha), r.beyond_p = p[k];
    r.spread = t[3 * j + 1], r.spread_critical = critical_value(sorted[k + 1], options.alpha), r.spread_p = p[k + 1];
    r.mean = t[3 * j + 2], r.mean_critical = critical_value(sorted[k + 2], options.alpha), r.mean_p = p[k + 2];
    out.estimates.push_back(r);
  }
  out.min_p = *std::min_element(p.begin(), p.end());
  // The family: the table's least p against each null file's own least p
  // (every null file's p read against the same null files), and jointly with
  // G₊'s p, so that a file is called significant at alpha by either.
  std::vector<double> sorted_unmodelled = null.unmodelled;
  std::sort(sorted_unmodelled.begin(), sorted_unmodelled.end());
  const double observed_combined = std::min(out.min_p, unmodelled_p);
  double family = 0, combined = 0;
  for (std::size_t b = 0; b < B; ++b) {
    double least = 1;
    for (Eigen::Index k = 0; k < K; ++k) least = std::min(least, upper_p(boot[b][k], sorted[static_cast<std::size_t>(k)]));
    family += least <= out.min_p;
    const double g = b < null.unmodelled.size() ? upper_p(null.unmodelled[b], sorted_unmodelled) : 1.0;
    combined += std::min(least, g) <= observed_combined;
  }
  out.family_p = (1.0 + family) / (1.0 + static_cast<double>(B));
  out.combined_p = (1.0 + combined) / (1.0 + static_cast<double>(B));
  out.significant = out.family_p < options.alpha;
  out.measured = true;
  return out;
}

}  // namespace insmc::gap
