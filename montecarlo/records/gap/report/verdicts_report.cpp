#include "montecarlo/records/gap/report/verdicts_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <optional>
#include <vector>

namespace insmc::gap {
namespace {

/// One verdict as the report states it: G, G₊ and G₋ against one null.
struct Verdict {
  const char* name;  ///< what it compares: "the model", "the unit's own noise"
  const char* null;  ///< the null files it is judged against
  const char* more;  ///< what G₊ beyond the null means
  double gap, median, gap_critical;
  double more_value, more_critical, more_p;
  bool more_significant;
  double less_value, less_critical, less_p;
  bool less_significant;
  /// G₊ and the test run's estimates against the prior jointly (the model's
  /// verdict when the estimates were measured): its p and decision.
  std::optional<double> joint_p;
  bool joint_significant = false;
};

Verdict against_model(const Diagnosis& d) {
  const bool imported = has_own_noise_verdict(d);
  Verdict v{"the model",
            imported ? "truth-level runs of the model (Table 3.1's priors) with a perfect sensor, through the same "
                       "import"
                     : "truth-level runs of the model itself (Table 3.1's priors)",
            "an unmodelled effect",
            imported ? d.against_model.gap : d.gap,
            imported ? d.against_model.null_gap_median : d.null_gap_median,
            imported ? d.against_model.null_gap_critical : d.null_gap_critical,
            imported ? d.against_model.value : d.unmodelled_gap,
            imported ? d.against_model.critical : d.unmodelled_critical,
            imported ? d.against_model.p_value : d.p_value,
            // G₊ judged on its own p; the estimates join it below.
            imported ? d.against_model.significant : d.p_value < d.alpha,
            d.pessimistic.value,
            d.pessimistic.critical,
            d.pessimistic.p_value,
            d.pessimistic.significant,
            std::nullopt,
            false};
  if (!imported && d.estimate_test.measured) {
    v.joint_p = d.estimate_test.combined_p;
    v.joint_significant = d.significant;
  }
  return v;
}

Verdict against_own_noise(const Diagnosis& d) {
  return {"the unit's own noise",
          "the same runs, each also carrying the raw stage's fitted noise, synthesized and imported as the records "
          "were",
          "an effect beyond the sensor's own noise",
          d.gap,
          d.null_gap_median,
          d.null_gap_critical,
          d.unmodelled_gap,
          d.unmodelled_critical,
          d.p_value,
          d.significant,
          d.own_noise_less.value,
          d.own_noise_less.critical,
          d.own_noise_less.p_value,
          d.own_noise_less.significant,
          std::nullopt,
          false};
}

/// The priors' scale that fits the runs, read for what it says.
std::string prior_scale_sentence(const PessimisticFinding& f) {
  const PriorScale& s = f.prior_scale;
  if (!s.measured) return "";
  const std::string value =
      s.at_limit ? fmt::format("{:.3g} or beyond (the end of its range, 0.01 to 100)", s.scale)
                 : fmt::format("{:.3g} (16–84 % of resampled fits {:.3g}–{:.3g}, on a grid of step ×1.33)", s.scale, s.low, s.high);
  return fmt::format(". Table 3.1's priors scaled by s = {} fit these runs best; with them G- = {:.3g}, {}", value,
                     s.pessimistic_after,
                     s.explains ? "within the null: priors that wide account for it"
                                : fmt::format("still beyond the null's {:.3g}: the priors alone do not account for "
                                              "it, another assumption is coarser than the data",
                                              f.critical));
}

std::string verdict_line(const Verdict& v, int runs, double alpha) {
  const std::string joint =
      v.joint_p && v.joint_significant != v.more_significant
          ? fmt::format("; jointly with the test run's estimates against the prior (below), p = {:.3g}: **{}**",
                        *v.joint_p, v.joint_significant ? "significant gap" : "no significant gap")
          : std::string();
  return fmt::format("G = **{:.3g}** (null files of {} runs: median {:.3g}, critical {:.3g}). More than {} ({}): G+ = "
                     "{:.3g}, p = {:.3g}, alpha = {}: **{}**{}. Less than {}: G- = {:.3g}, p = {:.3g} (critical {:.3g})",
                     v.gap, runs, v.median, v.gap_critical, v.name, v.more, v.more_value, v.more_p, alpha,
                     v.more_significant ? "significant gap" : "no significant gap", joint, v.name, v.less_value,
                     v.less_p, v.less_critical);
}

mc::Json verdict_json(const Verdict& v) {
  mc::Json j = mc::Json::object();
  j["against"] = v.name;
  j["null"] = v.null;
  j["value"] = v.gap;
  j["null_median"] = v.median;
  j["null_critical"] = v.gap_critical;
  const auto one_sided = [](double value, double critical, double p_value, bool significant) {
    mc::Json side = mc::Json::object();
    side["value"] = value;
    side["critical"] = critical;
    side["p_value"] = p_value;
    side["significant"] = significant;
    return side;
  };
  j["more"] = one_sided(v.more_value, v.more_critical, v.more_p, v.more_significant);
  j["less"] = one_sided(v.less_value, v.less_critical, v.less_p, v.less_significant);
  return j;
}

std::string short_verdict(const Verdict& v) {
  return fmt::format("{} (G+ = {:.3g}, p = {:.3g})", v.more_significant ? "a significant gap" : "no significant gap",
                     v.more_value, v.more_p);
}

}  // namespace

std::string verdicts_markdown(const Diagnosis& d) {
  const Verdict model = against_model(d);
  const std::string pessimistic =
      d.pessimistic.significant
          ? fmt::format(": **the model is pessimistic about {}**: the data scatter or share less there than it "
                        "predicts, so an assumption is wider than the data (a declared pulse weight or resolution "
                        "coarser than the data show, priors wider than this system); no effect is sought for it",
                        fmt::join(d.where.pessimistic_where, ", "))
          : ": not beyond the null";
  if (!has_own_noise_verdict(d))
    return fmt::format("**Against {}**, judged on null files of {}. ", model.name, model.null) +
           verdict_line(model, d.runs, d.alpha) + pessimistic + prior_scale_sentence(d.pessimistic) + ".\n\n";
  const Verdict own = against_own_noise(d);
  std::string md = fmt::format(
      "Two verdicts, in this order: against {} (Table 3.1's priors; sections 2 to 4 are against it), then against "
      "{} (what the raw-sensor stage fitted to the recordings).\n\n",
      model.name, own.name);
  md += fmt::format("1. **Against {}**, judged on null files of {}. ", model.name, model.null) +
        verdict_line(model, d.runs, d.alpha) + pessimistic + prior_scale_sentence(d.pessimistic) + ".\n";
  md += fmt::format("2. **Against {}**, judged on null files of {}. ", own.name, own.null) +
        verdict_line(own, d.runs, d.alpha) +
        (own.less_significant ? ": the raw stage's fitted noise is more than these records show" : ": not beyond the null") +
        ".\n\n";
  if (model.more_significant && !own.more_significant)
    md += "The gap against the model is what the sensor's own noise makes of the navigation errors through the "
          "import: nothing beyond it is found. Sections 2 to 4 show the gap against the model and which candidate "
          "describes it.\n\n";
  else if (own.more_significant)
    md += "The records show more than the sensor's own noise through the import: an effect beyond it. Sections 2 to "
          "4 show the gap against the model; the band of the sensor's own noise is drawn beside the model's.\n\n";
  return md;
}

std::string verdicts_sentence(const Diagnosis& d) {
  std::string s = "Against the model: " + short_verdict(against_model(d));
  if (has_own_noise_verdict(d)) s += "; against the unit's own noise through the import: " + short_verdict(against_own_noise(d));
  return s + ".";
}

mc::Json verdicts_json(const Diagnosis& d) {
  mc::Json j = mc::Json::array();
  j.push_back(verdict_json(against_model(d)));
  if (has_own_noise_verdict(d)) j.push_back(verdict_json(against_own_noise(d)));
  return j;
}

}  // namespace insmc::gap
