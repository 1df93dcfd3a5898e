#include "montecarlo/records/gap/report/report.h"

#include "montecarlo/records/gap/report/leading_finding.h"

#include <cmath>
#include <fmt/format.h>

#include "lib/units/quantity.h"
#include "lib/units/quantity_display.h"
#include "montecarlo/records/gap/report/estimate_report.h"
#include "montecarlo/records/gap/report/gap_plots.h"
#include "montecarlo/records/gap/report/likelihood_report.h"
#include "montecarlo/records/gap/report/verdicts_report.h"
#include "montecarlo/report/markdown.h"

namespace insmc::gap {
namespace {

/// The options of `insmc simulate` that reproduce the records' site (system,
/// latitude, test run, pulse weight, position resolution): an effect alone
/// would be simulated at simulate's defaults (45 deg), not at this site.
std::string simulate_site_options(const std::vector<runs::SiteValue>& site) {
  std::string out;
  for (const runs::SiteValue& v : site) {
    const std::string x = fmt::format("{:.10g}", v.value);
    if (v.key == "system") out += " --system " + x;
    else if (v.key == "latitude_deg") out += " --latitude " + x + "deg";
    else if (v.key == "test_duration_s") out += " --test-duration " + x + "s";
    else if (v.key == "filter_interval_s") out += " --filter-interval " + x + "s";
    else if (v.key == "dv_pulse_mps") out += " --dv-pulse " + x + "mps";
    else if (v.key == "position_resolution_m") out += " --position-resolution " + x + "m";
  }
  return out;
}

mc::Json shares_json(const std::vector<Share>& shares) {
  mc::Json j = mc::Json::object();
  for (const Share& s : shares) j[s.name] = s.share;
  return j;
}

mc::Json parameters_json(const std::vector<ParameterEstimate>& ps) {
  mc::Json j = mc::Json::object();
  for (const ParameterEstimate& p : ps) {
    mc::Json e = mc::Json::object();
    e["value"] = p.value;
    e["low_16"] = p.low;
    e["high_84"] = p.high;
    e["unit"] = std::string(si_suffix(p.dimension));
    e["at_grid_edge"] = p.at_grid_edge;
    if (p.check.measured) {
      // The fit on files simulated with the finding (ranking/finding_check.h).
      mc::Json c = mc::Json::object();
      c["files"] = p.check.files;
      c["simulated"] = p.check.simulated;
      c["scale"] = p.check.logarithmic ? "log" : "linear";
      c["bias"] = p.check.bias;
      c["spread"] = p.check.spread;
      e["simulated_check"] = c;
    }
    j[p.name] = e;
  }
  return j;
}

/// What the first-ranked finding's check on simulated files measured and did
/// to its values (ranking/finding_check.h).
std::string checked_markdown(const CandidateResult& top) {
  std::vector<std::string> parts;
  int files = 0;
  for (const ParameterEstimate& p : top.parameters) {
    if (!p.check.measured) continue;
    files = p.check.files;
    parts.push_back(p.check.logarithmic
                        ? fmt::format("{} fitted {:.3g}× the value simulated (spread {:.2g} in ln)", p.name,
                                      std::exp(p.check.bias), p.check.spread)
                        : fmt::format("{} fitted {} off the value simulated (spread {})", p.name,
                                      format_quantity_rounded(p.check.bias, p.dimension),
                                      format_quantity_rounded(p.check.spread, p.dimension)));
  }
  if (parts.empty()) return "";
  return fmt::format("Its values and ranges above are corrected for the fit's own bias, measured on {} files of the "
                     "records' size simulated with it and fitted the same way: {}; each range is widened by that "
                     "bias' standard error.\n\n",
                     files, fmt::join(parts, "; "));
}

std::string params_text(const std::vector<ParameterEstimate>& ps) {
  std::string s;
  for (const ParameterEstimate& p : ps) {
    s += (s.empty() ? "" : ", ") +
         fmt::format("{} = {} [{} … {}]{}", p.name, format_quantity_rounded(p.value, p.dimension),
                     format_quantity_rounded(p.low, p.dimension), format_quantity_rounded(p.high, p.dimension),
                     p.at_grid_edge ? " (grid edge)" : "");
  }
  return s;
}

std::string pct(double v) { return fmt::format("{:.1f} %", 100.0 * v); }

mc::Json diagnosis_json(const Diagnosis& d, const std::vector<std::string>& record_files) {
  mc::Json j = mc::Json::object();
  mc::Json files = mc::Json::array();
  for (const std::string& f : record_files) files.push_back(f);
  j["records"] = files;
  j["runs"] = d.runs;
  j["scheme"] = d.scheme;
  j["site"] = runs::site_values_json(d.site);
  mc::Json g = mc::Json::object();
  g["value"] = d.gap;
  g["significant"] = d.significant;
  g["alpha"] = d.alpha;
  g["p_value"] = d.p_value;
  g["null_median"] = d.null_gap_median;
  g["null_critical"] = d.null_gap_critical;
  g["calibration_runs"] = d.calibration_runs;
  mc::Json unmodelled = mc::Json::object();
  unmodelled["value"] = d.unmodelled_gap;
  unmodelled["critical"] = d.unmodelled_critical;
  unmodelled["p_value"] = d.p_value;
  g["unmodelled"] = unmodelled;
  mc::Json pessimistic = mc::Json::object();
  pessimistic["value"] = d.pessimistic.value;
  pessimistic["significant"] = d.pessimistic.significant;
  pessimistic["p_value"] = d.pessimistic.p_value;
  pessimistic["critical"] = d.pessimistic.critical;
  mc::Json where_less = mc::Json::array();
  for (const std::string& w : d.where.pessimistic_where) where_less.push_back(w);
  pessimistic["where"] = where_less;
  if (const PriorScale& ps = d.pessimistic.prior_scale; ps.measured) {
    mc::Json scale = mc::Json::object();
    scale["value"] = ps.scale;
    scale["low"] = ps.low;
    scale["high"] = ps.high;
    scale["at_limit"] = ps.at_limit;
    scale["pessimistic_after"] = ps.pessimistic_after;
    scale["explains"] = ps.explains;
    pessimistic["prior_scale"] = scale;
  }
  g["pessimistic"] = pessimistic;
  g["estimates"] = estimate_test_json(d.estimate_test);
  g["verdicts"] = verdicts_json(d);
  g["null"] = d.null_kind;
  if (d.against_model.reported) {
    mc::Json m = mc::Json::object();
    m["value"] = d.against_model.value;
    m["critical"] = d.against_model.critical;
    m["p_value"] = d.against_model.p_value;
    m["significant"] = d.against_model.significant;
    m["gap"] = d.against_model.gap;
    m["null_critical"] = d.against_model.null_gap_critical;
    g["against_model"] = m;
  }
  g["significance"] = "significant: an unmodelled effect, one-sided: G+ (the groups with ln ratio > 0) against the "
                      "null files' G+ at alpha; pessimistic: the groups with ln ratio < 0 (G-), the same way";
  g["metric"] = "G = sqrt(mean over groups of ln(observed/expected)^2): scatter groups (mean normalized square per "
                "run) and coherent groups (what all runs share, one-sided), expectations calibrated on the null";
  j["gap"] = g;
  mc::Json where = mc::Json::object();
  where["by_kind"] = shares_json(d.where.by_kind);
  where["by_axis"] = shares_json(d.where.by_axis);
  where["by_stage"] = shares_json(d.where.by_stage);
  where["by_window"] = shares_json(d.where.by_window);
  mc::Json groups = mc::Json::array();
  for (const GroupResult& r : d.where.groups) {
    mc::Json e = mc::Json::object();
    e["group"] = r.name();
    e["kind"] = r.coherent ? "coherent" : "scatter";
    e["terms"] = r.count;
    e["power"] = r.power;
    e["null_power"] = r.null_power;
    e["log_ratio"] = r.log_ratio;
    e["p_value"] = r.p_value;
    e["share"] = r.share;
    if (std::isfinite(r.own_noise_low)) {
      e["own_noise_low"] = r.own_noise_low;
      e["own_noise_high"] = r.own_noise_high;
    }
    groups.push_back(e);
  }
  where["groups"] = groups;
  mc::Json tf = mc::Json::object();
  for (const TimeFunctionShares& t : d.where.time_functions) tf[std::string(1, "xyz"[t.axis])] = shares_json(t.shares);
  where["time_functions_nav_r"] = tf;
  mc::Json allan = mc::Json::object();
  for (const AllanCurve& c : d.where.allan) {
    mc::Json a = mc::Json::array();
    for (const AllanPoint& p : c.points) {
      mc::Json e = mc::Json::object();
      e["cluster_s"] = p.cluster_s;
      e["observed_mps2"] = p.observed;
      e["null_mps2"] = p.null;
      if (p.own_noise > 0) e["own_noise_mps2"] = p.own_noise;
      a.push_back(e);
    }
    allan[std::string(1, "xyz"[c.axis])] = a;
  }
  where["allan_f_residual"] = allan;
  j["where"] = where;
  mc::Json ranking = mc::Json::array();
  for (const CandidateResult& c : d.first.ranking) {
    mc::Json e = mc::Json::object();
    e["effect"] = c.effect;
    e["params"] = parameters_json(c.parameters);
    e["heldout_gap_after"] = c.heldout_gap_after;
    e["shrink"] = c.shrink;
    // The margin behind the first's standard error (resampled runs): what the
    // rules that keep the rows' first or make a class read; none for the first.
    e["behind_first_se"] = std::isfinite(c.behind_first_se) ? mc::Json(c.behind_first_se) : mc::Json(nullptr);
    e["null_shrink"] = std::isfinite(c.null_shrink) ? mc::Json(c.null_shrink) : mc::Json(nullptr);
    e["as_effect"] = c.as_effect.empty() ? mc::Json(nullptr) : mc::Json(c.as_effect);
    e["simulate_site_options"] = simulate_site_options(d.site);
    mc::Json kept = mc::Json::array();
    for (const std::string& k : c.as_effect_kept) kept.push_back(k);
    e["as_effect_kept"] = kept;
    mc::Json left = mc::Json::object();
    for (int g = 0; g < runs::kGroupCount; ++g)
      if (std::isfinite(c.heldout_log_ratios.scatter[g])) left[runs::group_name(g)] = c.heldout_log_ratios.scatter[g];
    for (int k = 0; k < runs::kCoherentCount; ++k)
      if (std::isfinite(c.heldout_log_ratios.coherent[static_cast<std::size_t>(k)]))
        left[runs::coherent_group_name(k)] = c.heldout_log_ratios.coherent[static_cast<std::size_t>(k)];
    e["heldout_log_ratios"] = left;
    add_likelihood_json(e, c.likelihood, d.runs);
    ranking.push_back(e);
  }
  j["ranked"] = d.ranked();
  j["heldout_gap_before"] = d.heldout_gap_before;
  j["ranking"] = ranking;
  j["pairs"] = pairs_json(d);
  j["top"] = d.first.top.empty() ? mc::Json(nullptr) : mc::Json(d.first.top);
  j["runner_up_margin"] = d.first.runner_up_margin;
  j["runner_up_margin_se"] = d.first.runner_up_margin_se;
  mc::Json greedy = mc::Json::array();
  for (const GreedyStep& s : d.greedy) {
    mc::Json e = mc::Json::object();
    e["effect"] = s.effect;
    e["params"] = parameters_json(s.parameters);
    e["heldout_gap"] = s.heldout_gap;
    e["p_value"] = s.p_value;
    greedy.push_back(e);
  }
  j["greedy"] = greedy;
  mc::Json selected = mc::Json::array();
  for (const std::string& s : d.selected) selected.push_back(s);
  j["selected"] = selected;
  j["finding"] = leading_finding(d);
  mc::Json outliers = mc::Json::object();
  outliers["threshold"] = d.outliers.threshold;
  outliers["count"] = d.outliers.count;
  outliers["isolated"] = d.outliers.isolated;
  mc::Json largest = mc::Json::array();
  for (const OutlierRow& o : d.outliers.largest) {
    mc::Json row = mc::Json::object();
    row["run"] = o.run;
    row["t_s"] = o.t_s;
    row["component"] = o.component;
    row["z"] = o.z;
    largest.push_back(row);
  }
  outliers["largest"] = largest;
  j["outliers"] = outliers;
  mc::Json unread = mc::Json::object();
  unread["read"] = d.unread.read;
  unread["unread"] = d.unread.unread;
  unread["beyond"] = d.unread.beyond;
  unread["runs_beyond"] = d.unread.runs_beyond;
  mc::Json farthest = mc::Json::array();
  for (const UnreadRow& o : d.unread.largest) {
    mc::Json row = mc::Json::object();
    row["run"] = o.run;
    row["t_s"] = o.t_s;
    row["component"] = o.component;
    row["deviation_m"] = o.deviation_m;
    row["bound_m"] = o.bound_m;
    farthest.push_back(row);
  }
  unread["largest"] = farthest;
  j["unread_rows"] = unread;
  mc::Json statements = mc::Json::array();
  for (const std::string& s : d.statements) statements.push_back(s);
  j["statements"] = statements;
  return j;
}

}  // namespace

mc::Report diagnosis_report(const Diagnosis& d, const std::vector<std::string>& record_files) {
  std::string md = "# Sim-to-real gap diagnosis\n\n**" + leading_finding(d) + "**\n\n";
  md += fmt::format("Records: {} ({} runs, scheme {}). Null files are drawn from {} truth-level runs at the "
                    "records' times, pulse weight, site and scheme{}.\n\n",
                    fmt::join(record_files, ", "), d.runs, d.scheme, d.calibration_runs,
                    has_own_noise_verdict(d) ? " (and as many again with the sensor's own noise through the import)" : "");
  md += "## 1. The gap\n\n";
  md += verdicts_markdown(d);
  md += estimate_test_markdown(d.estimate_test, d.alpha);
  md += "Site values (the null is simulated with them):\n\n";
  mc::Table site({"value", "used", "source", "why"});
  for (const runs::SiteValue& v : d.site) site.add_row({v.key, fmt::format("{:.6g}", v.value), v.source, v.reason});
  md += mc::render_markdown(site) + "\n";
  md += fmt::format("G is the RMS over report groups of ln(observed / expected): per run, how the data scatter about the "
        "model's prediction (scatter groups), and what all runs share (coherent groups: a design or site effect, "
        "one-sided); 0 when the data match the model, 1 for a factor e ≈ 2.7 in power (too much or too little). "
        "G² = G+² + G-²: G+ from the groups above the model (what an effect would add), G- from those below it; "
        "each is tested one-sided against its own null distribution. The expectations are the model's own, "
        "calibrated on its null runs{}.\n\n",
        has_own_noise_verdict(d) ? " (for the verdict against the unit's own noise: on its null runs through the import)"
                                 : "");
  for (const std::string& s : d.statements) md += "- " + s + "\n";
  if (!d.statements.empty()) md += "\n";
  md += "## 2. Where it lies\n\n";
  const bool own_noise = has_own_noise_verdict(d);
  md += own_noise ? "Against the model (verdict 1): each group's observed power, the model's expectation, their ln "
                    "ratio and its p on the model's null files. The last column is the band (alpha/2 to 1 - alpha/2) "
                    "the sensor's own noise through the import puts that ln ratio in (verdict 2's null files read "
                    "with the model's expectation): a group inside it is the sensor's noise.\n\n"
                  : "Against the model: each group's observed power, the model's expectation, their ln ratio and its "
                    "p on the model's null files.\n\n";
  std::vector<std::string> columns{"group", "terms", "observed", "null", "ln ratio", "p", "share"};
  if (own_noise) columns.push_back("own-noise band");
  mc::Table t(columns);
  for (const GroupResult& r : d.where.groups) {
    std::vector<std::string> row{r.name(), fmt::format("{:.0f}", r.count), fmt::format("{:.3g}", r.power),
                                 fmt::format("{:.3g}", r.null_power), fmt::format("{:+.3f}", r.log_ratio),
                                 fmt::format("{:.3g}", r.p_value), pct(r.share)};
    if (own_noise)
      row.push_back(std::isfinite(r.own_noise_low) ? fmt::format("[{:+.2f}, {:+.2f}]", r.own_noise_low, r.own_noise_high)
                                                   : std::string("—"));
    t.add_row(row);
  }
  md += mc::render_markdown(t) + "\n";
  const auto share_line = [](const char* title, const std::vector<Share>& s) {
    std::string line = std::string("- ") + title + ": ";
    for (std::size_t i = 0; i < s.size(); ++i) line += (i ? ", " : "") + s[i].name + " " + pct(s[i].share);
    return line + "\n";
  };
  md += share_line("by kind", d.where.by_kind) + share_line("by axis", d.where.by_axis) + share_line("by stage", d.where.by_stage) +
        share_line("by window", d.where.by_window);
  md += "\nPost-test position innovations on the error's time functions (share of the normalized energy, fitted in "
        "this order):\n\n";
  mc::Table tf({"axis", "function", "share"});
  for (const TimeFunctionShares& s : d.where.time_functions)
    for (const Share& e : s.shares) tf.add_row({std::string(1, "xyz"[s.axis]), e.name, pct(e.share)});
  md += mc::render_markdown(tf) + "\n![group ln ratios](gap_groups.png)\n\n![Allan deviation](gap_allan.png)\n\n";
  md += "## 3. Which effect\n\n";
  if (!d.ranked()) {
    md += "Not ranked (see the statements above).\n\n";
  } else {
    md += fmt::format("Held-out G before: {:.3g} (against the model{}). Each candidate fitted on one half of the "
                      "runs, scored on the other (2-fold), ranked by held-out G after.\n\n",
                      d.heldout_gap_before, own_noise ? ", verdict 1" : "");
    mc::Table r({"rank", "effect", "held-out G after", "shrink", "shrink on null files", "parameters (16–84 % of resampled fits)"});
    for (std::size_t i = 0; i < d.first.ranking.size(); ++i)
      r.add_row({std::to_string(i + 1), d.first.ranking[i].effect, fmt::format("{:.3g}", d.first.ranking[i].heldout_gap_after),
                 pct(d.first.ranking[i].shrink),
                 std::isfinite(d.first.ranking[i].null_shrink) ? pct(d.first.ranking[i].null_shrink) : std::string("—"),
                 params_text(d.first.ranking[i].parameters)});
    md += "The shrink on null files is what the same candidate gains, split and fitted the same way, on null files "
          "of as many runs (runs of the null calibration): a shrink not above it is noise fitted, not an effect.\n\n";
    md += mc::render_markdown(r) + "\n";
    md += fmt::format("Top: **{}**; runner-up margin {:.3g} ± {:.3g} (resampled runs){}.\n\n", d.first.top,
                      d.first.runner_up_margin, d.first.runner_up_margin_se,
                      d.first.top.find('|') != std::string::npos ? " — within two standard errors: reported as one class" : "");
    if (!d.first.ranking.front().as_effect.empty()) {
      const CandidateResult& top = d.first.ranking.front();
      md += fmt::format("The first-ranked finding as an effect, to simulate and compare at this site (`insmc "
                        "simulate --effect {}{}`){}.\n\n", top.as_effect, simulate_site_options(d.site),
                        top.as_effect_kept.empty() ? ""
                                                   : fmt::format("; not fitted from the records: {}",
                                                                 fmt::join(top.as_effect_kept, "; ")));
      md += checked_markdown(top);
    }
    md += likelihood_markdown(d);
  }
  md += "## 4. How far it shrinks\n\n";
  if (d.greedy.empty()) {
    md += "No effect added.\n";
  } else {
    mc::Table g({"step", "effect added", "parameters", "held-out G", "p"});
    for (std::size_t i = 0; i < d.greedy.size(); ++i)
      g.add_row({std::to_string(i + 1), d.greedy[i].effect, params_text(d.greedy[i].parameters),
                 fmt::format("{:.3g}", d.greedy[i].heldout_gap), fmt::format("{:.3g}", d.greedy[i].p_value)});
    md += fmt::format("From held-out G = {:.3g} (against the model):\n\n", d.heldout_gap_before) + mc::render_markdown(g);
  }
  mc::Report report(diagnosis_report_outline());
  report.file("gap.md", std::move(md))
      .file("gap.json", diagnosis_json(d, record_files).dump(2) + "\n")
      .figure("gap_groups", [script = groups_figure_script(d)] { return mc::render_figure("gap_groups", script); })
      .figure("gap_allan", [figure = allan_figure(d)] { return mc::render_panel_figure(figure); })
      .shown_file(mc::ReportFormat::kMarkdown, "gap.md")
      .shown_file(mc::ReportFormat::kJson, "gap.json");
  return report;
}

mc::ReportOutline diagnosis_report_outline() {
  return {"gap",
          {"gap.md", "gap.json"},
          {"gap_groups", "gap_allan"},
          {mc::ReportFormat::kMarkdown, mc::ReportFormat::kJson}};
}

}  // namespace insmc::gap
