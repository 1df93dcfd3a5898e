#include "montecarlo/records/gap/report/estimate_report.h"

#include <fmt/format.h>

#include "montecarlo/report/markdown.h"

namespace insmc::gap {

mc::Json estimate_test_json(const EstimateTest& t) {
  mc::Json j = mc::Json::object();
  j["measured"] = t.measured;
  if (!t.measured) {
    j["reason"] = t.reason;
    return j;
  }
  j["min_p"] = t.min_p;
  j["family_p"] = t.family_p;
  j["significant"] = t.significant;
  j["combined_p"] = t.combined_p;
  mc::Json rows = mc::Json::array();
  for (const EstimateStatistics& e : t.estimates) {
    mc::Json r = mc::Json::object();
    r["estimate"] = e.name;
    r["reach"] = e.reach;
    const auto stat = [](double v, double c, double p) {
      mc::Json s = mc::Json::object();
      s["value"] = v;
      s["critical"] = c;
      s["p_value"] = p;
      return s;
    };
    r["beyond_reach"] = stat(e.beyond, e.beyond_critical, e.beyond_p);
    r["spread"] = stat(e.spread, e.spread_critical, e.spread_p);
    r["mean"] = stat(e.mean, e.mean_critical, e.mean_p);
    rows.push_back(r);
  }
  j["estimates"] = rows;
  mc::Json scores = mc::Json::array();
  for (const EstimateScore& s : t.scores) {
    mc::Json e = mc::Json::object();
    e["effect"] = s.effect;
    e["heldout_gain"] = s.heldout_gain;
    scores.push_back(e);
  }
  j["scores"] = scores;
  j["named"] = t.named.empty() ? mc::Json(nullptr) : mc::Json(t.named);
  j["replaced_top"] = t.replaced_top.empty() ? mc::Json(nullptr) : mc::Json(t.replaced_top);
  j["told_apart_by"] = t.told_apart_by.empty() ? mc::Json(nullptr) : mc::Json(t.told_apart_by);
  j["test"] = "per estimate of x the test run resolves (normalized, run_analysis.h): the share of runs beyond the "
              "null runs' 99 % point of |estimate|, the variance over runs over the null runs', |mean − null mean| "
              "in null standard errors; critical values and p from the null files of G; family_p: the least p "
              "against the null files' least p; combined_p: min(p of G+, least p) against the same of the null files";
  return j;
}

std::string estimate_test_markdown(const EstimateTest& t, double alpha) {
  if (!t.measured) return t.reason.empty() ? "" : "Estimates against the prior: not tested (" + t.reason + ").\n\n";
  std::string md = fmt::format(
      "**The test run's estimates against the prior.** Each estimate of Table 3.1's x that every run resolves, "
      "over its expected std, against the null runs (Table 3.1's uniform draws through the same estimators): the "
      "share of runs beyond the prior's reach (the null runs' 99 % point), the spread over the null's, the mean "
      "against the null's in standard errors. Critical values at alpha = {} and p from the null files of the gap. "
      "Least p {:.3g}; over the table (against the null files' least p) p = {:.3g}: **{}**; jointly with G+ "
      "p = {:.3g}.\n\n",
      alpha, t.min_p, t.family_p, t.significant ? "beyond the prior" : "within the prior", t.combined_p);
  mc::Table table({"estimate", "reach", "beyond", "critical", "p", "spread", "critical", "p", "mean", "critical", "p"});
  for (const EstimateStatistics& e : t.estimates)
    table.add_row({e.name, fmt::format("{:.3g}", e.reach), fmt::format("{:.2f}", e.beyond),
                   fmt::format("{:.2f}", e.beyond_critical), fmt::format("{:.3g}", e.beyond_p),
                   fmt::format("{:.3g}", e.spread), fmt::format("{:.3g}", e.spread_critical),
                   fmt::format("{:.3g}", e.spread_p), fmt::format("{:.3g}", e.mean), fmt::format("{:.3g}", e.mean_critical),
                   fmt::format("{:.3g}", e.mean_p)});
  md += mc::render_markdown(table) + "\n";
  if (!t.scores.empty()) {
    md += "Candidates acting inside the priors, scored on the estimates alone (held-out log-likelihood gain, "
          "2-fold, nats): ";
    for (std::size_t i = 0; i < t.scores.size(); ++i)
      md += fmt::format("{}{} {:.3g}", i ? ", " : "", t.scores[i].effect, t.scores[i].heldout_gain);
    md += t.named.empty() ? ".\n\n" : fmt::format("; named **{}**{}.\n\n", t.named,
                                                  t.told_apart_by.empty() ? "" : " (" + t.told_apart_by + ")");
  }
  return md;
}

}  // namespace insmc::gap
