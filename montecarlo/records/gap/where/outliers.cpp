#include "montecarlo/records/gap/where/outliers.h"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <fmt/format.h>
#include <string>

namespace insmc::gap {

Outliers find_outliers(const runs::PreparedRuns& p, const std::vector<std::optional<runs::RunAnalyser>>& analysers,
                       const std::vector<Eigen::VectorXd>& null_z, double alpha) {
  Outliers out;
  double null_largest = 0.0;
  for (const Eigen::VectorXd& z : null_z)
    if (z.size() > 0) null_largest = std::max(null_largest, z.cwiseAbs().maxCoeff());
  std::size_t rows = 0;
  for (const runs::RunData& r : p.runs) rows += r.layout.rows.size();
  if (rows == 0) return out;
  const double bonferroni =
      boost::math::quantile(boost::math::normal(), 1.0 - alpha / (2.0 * static_cast<double>(rows)));
  out.threshold = std::max(bonferroni, 2.0 * null_largest);
  for (std::size_t j = 0; j < p.runs.size(); ++j) {
    const runs::RunData& run = p.runs[j];
    Eigen::VectorXd z;
    analysers[static_cast<std::size_t>(p.layout_of[j])]->analyse(runs::run_values(run), z);
    // One row per run, its largest: a corrupt test-run row moves the run's
    // fit, and every row of the run then follows it.
    Eigen::Index at = 0;
    if (z.size() == 0 || !(z.cwiseAbs().maxCoeff(&at) > out.threshold)) continue;
    ++out.count;
    const runs::ObservationRow& row = run.layout.rows[static_cast<std::size_t>(at)];
    out.largest.push_back({run.id, row.t_s,
                           fmt::format("{}_{}", row.quantity == runs::Quantity::kF ? "f" : "r", "xyz"[row.axis]),
                           z[at]});
  }
  out.isolated = out.count > 0 && out.count <= std::max(1, static_cast<int>(p.runs.size() / 10));
  std::stable_sort(out.largest.begin(), out.largest.end(),
                   [](const OutlierRow& a, const OutlierRow& b) { return std::abs(a.z) > std::abs(b.z); });
  if (out.largest.size() > static_cast<std::size_t>(kListedOutliers)) out.largest.resize(kListedOutliers);
  return out;
}

std::string outliers_sentence(const Outliers& o) {
  if (!o.isolated || o.largest.empty()) return "";
  const OutlierRow& first = o.largest.front();
  const bool one = o.count == 1;
  return fmt::format("{} beyond {:.3g} σ of the model ({}run {} at t = {:g} s, {}, {:.3g} σ): a corrupt record or a "
                     "jump in the logger, not an effect the candidates model; check {}, the diagnosis below includes "
                     "{}.",
                     one ? std::string("A run has a record") : fmt::format("{} runs have a record", o.count),
                     o.threshold, one ? "" : "the largest: ", first.run, first.t_s, first.component, std::abs(first.z),
                     one ? "it" : "them", one ? "it" : "them");
}

}  // namespace insmc::gap
