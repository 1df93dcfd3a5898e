#include "montecarlo/records/gap/report/likelihood_report.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

#include "lib/units/quantity.h"
#include "lib/units/quantity_display.h"
#include "montecarlo/report/markdown.h"

namespace insmc::gap {
namespace {

mc::Json number(double v) { return std::isfinite(v) ? mc::Json(v) : mc::Json(nullptr); }

mc::Json parameters_json(const std::vector<MlParameter>& ps) {
  mc::Json out = mc::Json::array();
  for (const MlParameter& p : ps) {
    mc::Json e = mc::Json::object();
    e["name"] = p.name;
    e["value"] = p.value;
    e["unit"] = std::string(si_suffix(p.dimension));
    e["fit"] = p.least_squares ? "least squares" : "maximum likelihood";
    const auto end = [&](double v) { return p.intervals ? mc::Json(v) : mc::Json(nullptr); };
    e["low68"] = end(p.ci68.low);
    e["high68"] = end(p.ci68.high);
    e["low95"] = end(p.ci95.low);
    e["high95"] = end(p.ci95.high);
    // An open end stays within the drop up to the physical limit it reports.
    mc::Json open = mc::Json::array();
    if (p.intervals) {
      if (p.ci68.open_low) open.push_back("low68");
      if (p.ci68.open_high) open.push_back("high68");
      if (p.ci95.open_low) open.push_back("low95");
      if (p.ci95.open_high) open.push_back("high95");
    }
    e["open"] = open;
    e["at_limit"] = p.at_limit;
    out.push_back(e);
  }
  return out;
}

std::string gain_text(double gain, int runs) {
  return std::isfinite(gain) ? fmt::format("{:+.1f} ({:+.2f}/run)", gain, gain / runs) : std::string("—");
}

std::string interval_text(const ProfileRange& r, Dimension d) {
  return fmt::format("[{}{} … {}{}]", r.open_low ? "limit " : "", format_quantity_rounded(r.low, d),
                     r.open_high ? "limit " : "", format_quantity_rounded(r.high, d));
}

std::string parameters_text(const std::vector<MlParameter>& ps) {
  std::string s;
  for (const MlParameter& p : ps) {
    s += (s.empty() ? "" : "; ") + p.name + " = " + format_quantity_rounded(p.value, p.dimension);
    if (p.least_squares) s += " (least squares)";
    if (p.intervals) s += " " + interval_text(p.ci68, p.dimension) + " " + interval_text(p.ci95, p.dimension);
    if (p.at_limit) s += p.least_squares ? " (held at the magnitude it covers)" : " (runs to its physical limit)";
  }
  return s;
}

}  // namespace

void add_likelihood_json(mc::Json& entry, const LikelihoodResult& r, int runs) {
  entry["ml_parameters"] = parameters_json(r.parameters);
  entry["heldout_loglik_gain"] = number(r.heldout_gain);
  entry["heldout_loglik_gain_per_run"] = number(r.heldout_gain / runs);
  entry["null_loglik_gain"] = number(r.null_gain);
  entry["ml_evaluations"] = r.evaluations;
}

mc::Json pairs_json(const Diagnosis& d) {
  mc::Json out = mc::Json::array();
  for (const PairResult& p : d.first.pairs) {
    mc::Json e = mc::Json::object();
    mc::Json effects = mc::Json::array();
    effects.push_back(p.first);
    effects.push_back(p.second);
    e["effects"] = effects;
    add_likelihood_json(e, p.likelihood, d.runs);
    out.push_back(e);
  }
  return out;
}

std::string likelihood_markdown(const Diagnosis& d) {
  const auto fitted = std::count_if(d.first.ranking.begin(), d.first.ranking.end(),
                                    [](const CandidateResult& c) { return c.likelihood.fitted; });
  if (fitted == 0) return {};
  std::string md = fmt::format(
      "### Maximum likelihood\n\nThe first {} candidates by held-out G, fitted again by maximum likelihood (the exact "
      "Gaussian likelihood of every run) with each parameter between its physical limits instead of the grid; "
      "intervals of the profile likelihood, 68 % then 95 %, \"limit\" where an end reaches a physical limit (open "
      "there). The held-out log-likelihood gain over the model without the candidate is 2-fold, as the ranking; on "
      "null files, the same gain on null files of as many runs: a gain not above it is noise fitted. The ranking "
      "stays by held-out G.\n\n",
      fitted);
  mc::Table t({"rank", "effect", "held-out log-likelihood gain [nats]", "on null files", "parameters [68 %] [95 %]"});
  for (std::size_t i = 0; i < d.first.ranking.size(); ++i) {
    const LikelihoodResult& r = d.first.ranking[i].likelihood;
    if (!r.fitted) continue;
    t.add_row({std::to_string(i + 1), d.first.ranking[i].effect, gain_text(r.heldout_gain, d.runs),
               gain_text(r.null_gain, d.runs), parameters_text(r.parameters)});
  }
  md += mc::render_markdown(t) + "\n";
  if (d.first.pairs.empty()) return md;
  md += "Pairs of the first candidates, both extensions together and their parameters fitted jointly (coordinate "
        "ascent, no intervals), by held-out log-likelihood gain:\n\n";
  mc::Table pt({"pair", "held-out log-likelihood gain [nats]", "on null files", "parameters"});
  for (const PairResult& p : d.first.pairs)
    pt.add_row({p.first + " + " + p.second, gain_text(p.likelihood.heldout_gain, d.runs),
                gain_text(p.likelihood.null_gain, d.runs), parameters_text(p.likelihood.parameters)});
  return md + mc::render_markdown(pt) + "\n";
}

}  // namespace insmc::gap
