#include "montecarlo/records/gap/report/leading_finding.h"

#include <cmath>
#include <fmt/format.h>
#include <vector>

#include "lib/units/units.h"
#include "montecarlo/records/gap/report/verdicts_report.h"
#include "montecarlo/records/gap/where/outliers.h"
#include "montecarlo/records/gap/where/unread_rows.h"

namespace insmc::gap {
namespace {

/// "the accelerometer pulses are 10 times the model's 0.1 ft/s (...)", or "".
std::string far_site_value(const runs::SiteValue& v, const char* what, double model, const char* model_text, double unit,
                           const char* unit_name) {
  if (!(v.value > 0) || !(model > 0)) return "";
  const double ratio = v.value / model;
  if (ratio < kFarFromModel && ratio > 1.0 / kFarFromModel) return "";
  return fmt::format("{} {:.3g} {} ({} {:.3g} times the model's {})", what, v.value / unit, unit_name,
                     v.source == "header" ? "stated in the header," : "inferred from the rows,", ratio, model_text);
}

/// The finding read from the runs themselves.
std::string finding_of_the_runs(const Diagnosis& d) {
  std::vector<std::string> far;
  for (const runs::SiteValue& v : d.site) {
    std::string s;
    if (v.key == "dv_pulse_mps") s = far_site_value(v, "accelerometer pulses of", 0.1 * kFtpsToMps, "0.1 ft/s", kFtpsToMps, "ft/s");
    if (v.key == "position_resolution_m") s = far_site_value(v, "a position resolution of", 3 * kFtToM, "3 ft", kFtToM, "ft");
    if (!s.empty()) far.push_back(s);
  }
  // Records through the import: both verdicts follow the first sentence, in the report's order.
  const std::string verdicts = has_own_noise_verdict(d) ? " " + verdicts_sentence(d) : std::string();
  if (d.raw_gyro_ratio > kFarFromModel || d.raw_accel_ratio > kFarFromModel)
    return fmt::format("The unit lies outside the model's priors: over one Schuler period its gyros' noise is {:.3g} "
                       "times and its accelerometers' {:.3g} times Table 3.1's bounds (raw-sensor stage){}. What the "
                       "ranking below names is the direction of that excess in the navigation residuals, not an effect "
                       "on top of a unit the model describes.{}",
                       d.raw_gyro_ratio, d.raw_accel_ratio,
                       far.empty() ? std::string() : fmt::format("; and its counts differ from the model's: {}", fmt::join(far, "; ")),
                       verdicts);
  if (has_own_noise_verdict(d) && far.empty() && !d.significant) {
    const std::string noise =
        fmt::format("over one Schuler period its gyros' noise is {:.3g} times and its accelerometers' {:.3g} times "
                    "Table 3.1's bounds (raw-sensor stage{})",
                    d.raw_gyro_ratio, d.raw_accel_ratio,
                    d.raw_gyro_ratio <= 1 && d.raw_accel_ratio <= 1 ? ": within them" : "");
    if (d.model_gap_significant())
      return fmt::format("The gap against the model is the unit's own sensor noise through the import, nothing "
                         "beyond it: {}.{}", noise, verdicts);
    return fmt::format("The data agree with the model and with the unit's own noise: {}.{}", noise, verdicts);
  }
  if (!far.empty())
    return fmt::format("The unit's counts lie outside the model's assumptions: {}. The gap below is measured against a "
                       "model with these counts; the paper's error budget (Table 3.1, chapter 5) assumes the report's.{}",
                       fmt::join(far, "; "), verdicts);
  const bool significant = d.model_gap_significant();
  if (significant && d.ranked() && !d.first.ranking.empty()) {
    for (const CandidateResult& c : d.first.ranking)
      if (c.effect == "bounds" && !c.parameters.empty() && d.first.top.find("bounds") != std::string::npos)
        return fmt::format("The unit lies outside the model's priors: Table 3.1's bounds widened {:.3g} times remove "
                           "{:.0f} % of the held-out gap (section 3).{}", c.parameters.front().value, 100 * c.shrink, verdicts);
    const CandidateResult& top = d.first.ranking.front();
    const std::string against_null =
        std::isfinite(top.null_shrink) ? fmt::format(", against {:.0f} % on null files", 100 * top.null_shrink)
                                       : std::string();
    if (!d.estimate_test.replaced_top.empty() && !d.estimate_test.scores.empty())
      // Named by the estimates against the prior, not by the residuals'
      // ranking: each with its own evidence.
      return fmt::format("An effect inside the priors: {} (named by the test run's estimates against the prior, "
                         "{} first at a held-out gain of {:.3g} nats, section 1). On the residuals the first-ranked "
                         "candidate, {}, closes {:.0f} % of the held-out gap{} (section 3).{}",
                         d.first.top, d.estimate_test.scores.front().effect, d.estimate_test.scores.front().heldout_gain,
                         top.effect, 100 * top.shrink, against_null, verdicts);
    return fmt::format("An unmodelled effect: {} (first-ranked; {}) closes {:.0f} % of the held-out gap{}.{}", d.first.top,
                       top.as_effect.empty() ? "parameters in section 3" : "as an effect: " + top.as_effect,
                       100 * top.shrink, against_null, verdicts);
  }
  if (significant)
    return "The data show more than the model predicts (a significant gap), not ranked here (section 3)." + verdicts;
  if (d.pessimistic.significant)
    return "The model is pessimistic: the data scatter or share less than it predicts (section 1), so an assumption "
           "is wider than the unit.";
  return "The data agree with the model: no significant gap in either direction.";
}

}  // namespace

std::string leading_finding(const Diagnosis& d) {
  // A corrupt record comes before anything read from the runs it is in.
  std::string first = outliers_sentence(d.outliers);
  if (const std::string unread = unread_rows_finding(d.unread); !unread.empty())
    first += (first.empty() ? "" : " ") + unread;
  const std::string rest = finding_of_the_runs(d);
  return first.empty() ? rest : first + " " + rest;
}

}  // namespace insmc::gap
