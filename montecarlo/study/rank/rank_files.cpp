#include "montecarlo/study/rank/rank_files.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "lib/units/units.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/interval_format.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/markdown.h"
#include "montecarlo/report/plot/panel_figure.h"
#include "montecarlo/study/write/study_writer.h"

namespace insmc::mc {
namespace {

std::string t_min_text(double t_s) { return format_number(t_s / 60.0); }

/// An assumption's value in the unit a navigation engineer reads it in
/// (a reset's errors in the lengths of --units: m and m/s, ft and ft/s, or
/// nmi and kt), with its SI value where that is another unit.
struct DisplayUnit {
  double per_si;
  std::string unit;
};

DisplayUnit display_unit(Assumption a, LengthUnit length) {
  const double per_m = length_factor(length);
  const std::string l = length_suffix(length);
  switch (a) {
    case Assumption::kAlignDriftError: return {1.0 / kMeruToRadps, "meru"};  // 1 meru = 1e-3 ω_ie
    case Assumption::kResetVelocityError:
      return length == LengthUnit::kNauticalMile ? DisplayUnit{3600.0 * per_m, "kt"} : DisplayUnit{per_m, l + "/s"};
    case Assumption::kResetPositionError: return {per_m, l};
    case Assumption::kRealignAzimuthError: return {1.0 / kMradToRad, "mrad"};
    case Assumption::kRandomFraction: return {1.0, ""};
    case Assumption::kTestDuration: return {1.0 / 60.0, "min"};
  }
  return {1.0, ""};
}

std::string value_text(Assumption a, double si, const StudyConfig& config, LengthUnit length) {
  if (std::isnan(si)) return "—";
  const DisplayUnit d = display_unit(a, length);
  const std::string shown = fmt::format("{:.3g}{}{}", si * d.per_si, d.unit.empty() ? "" : " ", d.unit);
  if (a == Assumption::kAlignDriftError)
    return fmt::format("{} ({:.3g} ω_ie, {:.3g} rad/s)", shown, si / config.model.earth_rate_radps, si);
  if (d.per_si == 1.0) return shown;  // already SI
  if (a == Assumption::kResetVelocityError) return fmt::format("{} ({:.3g} m/s)", shown, si);
  if (a == Assumption::kResetPositionError) return fmt::format("{} ({:.3g} m)", shown, si);
  if (a == Assumption::kRealignAzimuthError) return fmt::format("{} ({:.3g} rad)", shown, si);
  return shown;
}

/// The values an assumption's crossings were searched over: a bound's
/// catalogue range (solved exactly there; its curve in the figure spans
/// less), F's [0, 1], the test durations scanned (the curve's first and
/// last point).
std::string searched_range(const BreakEven& even, Assumption a, LengthUnit length) {
  const DisplayUnit d = display_unit(a, length);
  const std::string unit = d.unit.empty() ? "" : " " + d.unit;
  if (const int slot = bound_slot(a); slot >= 0)
    return fmt::format("0 to {:.3g}{}", bound_range(catalogue()[static_cast<std::size_t>(slot)]).max_si * d.per_si, unit);
  if (a == Assumption::kRandomFraction) return "0 to 1";
  for (const AssumptionCurve& c : even.curves)
    if (c.assumption == a && !c.values_si.empty())
      return fmt::format("{:.3g} to {:.3g}{}", c.values_si.front() * d.per_si, c.values_si.back() * d.per_si, unit);
  return "—";
}

/// "5.4 stays first while E4 < 1.1 meru (then 5.1.2)": the nearest
/// crossings below and above the study's value.
std::string limits_sentence(const StudyConfig& config, System system, double t_s, Assumption a, const BreakEven& even,
                            Scheme leader, LengthUnit length) {
  const std::vector<Crossing>& crossings = even.crossings;
  const double now = study_value(config, a);
  const Crossing* below = nullptr;
  const Crossing* above = nullptr;
  for (const Crossing& c : crossings) {
    if (c.system != system || c.t_s != t_s || c.assumption != a) continue;
    if (std::isnan(now) || c.value_si > now) {
      if (!above || c.value_si < above->value_si) above = &c;
    } else if (!below || c.value_si > below->value_si) {
      below = &c;
    }
  }
  const std::string name(to_string(a));
  if (!below && !above)
    return fmt::format("{} stays first over the whole searched range of {} ({})", to_string(leader), name,
                       searched_range(even, a, length));
  std::string s = fmt::format("{} stays first while ", to_string(leader));
  if (below)
    s += fmt::format("{} > {} (below: {})", name, value_text(a, below->value_si, config, length),
                     to_string(below->challenger));
  if (below && above) s += " and ";
  if (above)
    s += fmt::format("{} < {} (beyond: {})", name, value_text(a, above->value_si, config, length),
                     to_string(above->challenger));
  return s + fmt::format(" (searched: {})", searched_range(even, a, length));
}

/// "RMS ± half its interval" in the printed unit.
std::string rms_text(const RankedScheme& s, LengthUnit unit) {
  const double k = length_factor(unit);
  return format_with_interval(k * s.rms_m, k * (s.rms_hi_m - s.rms_lo_m) / 2);
}

std::string order_line(const SchemeOrder& o, LengthUnit unit) {
  std::string s;
  for (std::size_t r = 0; r < o.schemes.size(); ++r) {
    const RankedScheme& x = o.schemes[r];
    s += fmt::format("{} {}", to_string(x.scheme), rms_text(x, unit));
    if (r + 1 < o.schemes.size()) s += x.order_significant ? " < " : " ≈ ";
  }
  return s;
}

/// Per system, the first and second scheme at every time of the study
/// (report times and the grid): who leads when.
std::string first_place_over_time(const StudyConfig& config, const std::vector<SchemeOrder>& orders, LengthUnit unit) {
  const std::string rms_heading = fmt::format("RMS [{}]", length_suffix(unit));
  std::string md;
  for (System system : config.systems) {
    Table t({"t [min]", "first", rms_heading, "second", rms_heading, "order", "test"});
    for (const SchemeOrder& o : orders) {
      if (o.system != system || o.schemes.size() < 2) continue;
      const RankedScheme &a = o.schemes[0], &b = o.schemes[1];
      t.add_row({t_min_text(o.t_s), std::string(to_string(a.scheme)), rms_text(a, unit),
                 std::string(to_string(b.scheme)), rms_text(b, unit),
                 a.order_significant ? "significant" : "not significant", o.paired ? "paired" : "intervals"});
    }
    if (t.rows().empty()) continue;
    md += fmt::format("## System {}: the first place over time\n\n", system_number(system)) + render_markdown(t) + "\n";
  }
  return md;
}

/// Linear interpolation of the leader's curve at a crossing (the mark).
double curve_value(const AssumptionCurve& c, std::size_t j, std::size_t k, std::size_t i, double v) {
  for (std::size_t q = 0; q + 1 < c.values_si.size(); ++q) {
    const double a = c.values_si[q], b = c.values_si[q + 1];
    if (v >= a && v <= b) {
      const double w = b > a ? (v - a) / (b - a) : 0.0;
      return (1 - w) * c.rms[q][j][k][i] + w * c.rms[q + 1][j][k][i];
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

namespace {

/// The two tables the sections fill as they go.
struct RankFiles {
  std::string ranking_csv, breakeven_csv;
};

/// ranking.csv's rows and the orders' JSON: every order with its intervals and tests.
Json orders_section(const std::vector<SchemeOrder>& orders, const std::string& fidelity, LengthUnit unit,
                    RankFiles& f) {
  const std::string u = length_suffix(unit);
  const double per_m = length_factor(unit);
  Table ranking({"system", "t_min", "fidelity", "rank", "scheme", "rms_" + u, "rms_lo_" + u, "rms_hi_" + u,
                 "order_significant", "test"});
  Json orders_json = Json::array();
  for (const SchemeOrder& o : orders) {
    Json schemes = Json::array();
    for (std::size_t r = 0; r < o.schemes.size(); ++r) {
      const RankedScheme& s = o.schemes[r];
      const bool last = r + 1 == o.schemes.size();
      ranking.add_row({std::to_string(system_number(o.system)), t_min_text(o.t_s), fidelity, std::to_string(r + 1),
                       std::string(to_string(s.scheme)), format_number(per_m * s.rms_m),
                       format_number(per_m * s.rms_lo_m), format_number(per_m * s.rms_hi_m),
                       last ? "" : (s.order_significant ? "true" : "false"),
                       o.paired ? "paired" : "intervals"});
      Json j = Json::object();
      j["rank"] = static_cast<int>(r + 1);
      j["scheme"] = std::string(to_string(s.scheme));
      j["rms_m"] = s.rms_m;
      j["rms_lo_m"] = s.rms_lo_m;
      j["rms_hi_m"] = s.rms_hi_m;
      if (!last) {
        j["order_significant"] = s.order_significant;
        j["paired_z"] = std::isfinite(s.paired_z) ? Json(s.paired_z) : Json();
      }
      schemes.push_back(std::move(j));
    }
    Json oj = Json::object();
    oj["system"] = system_number(o.system);
    oj["t_s"] = o.t_s;
    oj["test"] = o.paired ? "paired" : "intervals";
    oj["paired_samples"] = static_cast<unsigned long long>(o.paired_samples);
    oj["schemes"] = std::move(schemes);
    orders_json.push_back(std::move(oj));
  }
  f.ranking_csv = render_csv(ranking);
  return orders_json;
}

/// breakeven.csv's rows and the crossings' JSON.
Json crossings_section(const BreakEven& even, const std::string& fidelity, RankFiles& f) {
  Table breakeven({"system", "t_min", "fidelity", "assumption", "leader", "challenger", "value", "unit"});
  Json crossings_json = Json::array();
  for (const Crossing& c : even.crossings) {
    breakeven.add_row({std::to_string(system_number(c.system)), t_min_text(c.t_s), fidelity,
                       std::string(to_string(c.assumption)), std::string(to_string(c.leader)),
                       std::string(to_string(c.challenger)), format_number(c.value_si), std::string(si_unit(c.assumption))});
    Json j = Json::object();
    j["system"] = system_number(c.system);
    j["t_s"] = c.t_s;
    j["assumption"] = std::string(to_string(c.assumption));
    j["leader"] = std::string(to_string(c.leader));
    j["challenger"] = std::string(to_string(c.challenger));
    j["value"] = c.value_si;
    j["unit"] = std::string(si_unit(c.assumption));
    crossings_json.push_back(std::move(j));
  }
  f.breakeven_csv = render_csv(breakeven);
  return crossings_json;
}

/// rank.md: the order with its significance, then the limits of the first place.
std::string rank_markdown(const StudyConfig& config, const std::vector<SchemeOrder>& orders, const BreakEven& even,
                          const std::string& fidelity, LengthUnit unit) {
  const std::string u = length_suffix(unit);
  std::string md = fmt::format(
      "# insmc rank: the schemes in order, and the assumptions that decide it\n\n"
      "Fidelity {}, {} samples, seed {}, confidence {:g} %. Order by the horizontal RMS of the Monte Carlo "
      "(interval: the RMS's {:g} % confidence interval over all samples). An adjacent pair's order is "
      "*significant* when the paired test says so: each sample passes through every scheme, so the difference "
      "of the two schemes' squared errors is tested against its own scatter (two-sided normal quantile of the "
      "confidence, over the kept samples: up to 2^24 values in all). On the envelope grid (ranking.csv, and the "
      "last table of each system below) the samples are not kept: there an order is significant when the two RMS "
      "intervals do not overlap, a weaker (unpaired) test.\n\n",
      fidelity, config.samples, config.seed, 100 * config.confidence, 100 * config.confidence);
  for (const SchemeOrder& o : orders) {
    if (!o.paired) continue;
    md += fmt::format("## System {}, {} min ({} paired samples)\n\n", system_number(o.system), t_min_text(o.t_s),
                      o.paired_samples);
    Table t({"rank", "scheme", fmt::format("RMS [{}] ± half-width", u), "order against the next, and by how much"});
    for (std::size_t r = 0; r < o.schemes.size(); ++r) {
      const RankedScheme& s = o.schemes[r];
      // The z says whether the order is real; the difference says whether
      // it matters (a 0.001 nmi lead can be significant with many samples).
      const std::string against =
          r + 1 == o.schemes.size()
              ? ""
              : fmt::format("{} (z = {:.3g}), the next {} {} larger",
                            s.order_significant ? "significant" : "not significant", s.paired_z,
                            format_significant(length_factor(unit) * (o.schemes[r + 1].rms_m - s.rms_m), 3), u);
      t.add_row({std::to_string(r + 1), std::string(to_string(s.scheme)), rms_text(s, unit), against});
    }
    md += render_markdown(t) + "\n";
  }
  md += first_place_over_time(config, orders, unit);
  std::string ranges;
  for (Assumption a : kAllAssumptions)
    if (const int slot = bound_slot(a); slot >= 0)
      ranges += fmt::format("{}{} up to {}", ranges.empty() ? "" : ", ", to_string(a),
                            value_text(a, bound_range(catalogue()[static_cast<std::size_t>(slot)]).max_si, config, unit));
  md += "## The first place's limits (covariance level, exact)\n\n"
        "Each assumption moved alone, the others at the study's values: a scheme measurement error as uniform ±b "
        "on each of its axes (alignment_drift_error is ω_ie E4 of (5.15); the reset errors act at T in (5.8); realignment_azimuth_error is system 1's theodolite re-sighting at the "
        "realignment of 5.1.x), the random "
        "fraction F of ζ and ∂f drawn anew at each alignment, the test duration on whole filter intervals "
        "(1 min to 40 min). A bound is searched over its catalogue range (" + ranges + "), F over 0 to 1. "
        "breakeven.csv lists every crossing of the first scheme with another.\n\n";
  Table limits({"system", "t [min]", "first", "assumption", "in the study", "searched", "limits of the first place"});
  for (std::size_t j = 0; j < even.at_study.size(); ++j)
    for (std::size_t k = 0; k < even.at_study[j].size(); ++k) {
      const auto& rms = even.at_study[j][k];
      const auto leader = leader_of(rms);
      for (Assumption a : kAllAssumptions)
        if (applies_to(a, config.systems[j]))
          limits.add_row({std::to_string(system_number(config.systems[j])), t_min_text(config.report_times_s[k]),
                        std::string(to_string(config.schemes[leader])), std::string(to_string(a)),
                        value_text(a, study_value(config, a), config, unit), searched_range(even, a, unit),
                        limits_sentence(config, config.systems[j], config.report_times_s[k], a, even,
                                        config.schemes[leader], unit)});
    }
  md += render_markdown(limits);
  return md;
}

/// stdout: the order and the limits at the last report time.
std::string rank_summary(const StudyConfig& config, const std::vector<SchemeOrder>& orders, const BreakEven& even,
                         LengthUnit unit) {
  const std::string u = length_suffix(unit);
  std::string text;
  const std::size_t last_k = config.report_times_s.size() - 1;
  for (const SchemeOrder& o : orders) {
    if (o.t_s != config.report_times_s[last_k]) continue;
    text += fmt::format("system {}, {} min: {}\n", system_number(o.system), t_min_text(o.t_s), order_line(o, unit));
  }
  text += fmt::format("(< : significant, ≈ : not significant; RMS in {})\n\n", u);
  for (std::size_t j = 0; j < even.at_study.size(); ++j) {
    const auto& rms = even.at_study[j][last_k];
    const auto leader = leader_of(rms);
    for (Assumption a : kAllAssumptions)
      if (applies_to(a, config.systems[j]))
        text += fmt::format("system {}, {} min: {}\n", system_number(config.systems[j]), t_min_text(config.report_times_s[last_k]),
                          limits_sentence(config, config.systems[j], config.report_times_s[last_k], a, even,
                                          config.schemes[leader], unit));
  }
  return text;
}

/// The figure: per assumption and system, every scheme's RMS at the last
/// report time, the crossings marked on the first scheme's line.
PanelFigure rank_plot(const StudyConfig& config, const BreakEven& even, const std::string& fidelity, LengthUnit unit) {
  PanelFigure plot;
  const std::string u = length_suffix(unit);
  const double per_m = length_factor(unit);
  const std::size_t last_k = config.report_times_s.size() - 1;
  plot.stem = "rank";
  plot.title = fmt::format("Horizontal RMS at {} min along each assumption ({} level; scheme none, which none "
                             "of them moves, left out; points: where the first place changes hands)",
                             t_min_text(config.report_times_s[last_k]), fidelity);
  plot.y_label = fmt::format("horizontal RMS [{}]", u);
  // Two panels a row (three beyond eight panels, both systems): one column
  // of six assumptions, or two of twelve, runs past an A4 page's height.
  plot.columns = config.systems.size() > 1 ? 3 : 2;
  for (const AssumptionCurve& c : even.curves) {
    const DisplayUnit d = display_unit(c.assumption, unit);
    for (std::size_t j = 0; j < config.systems.size(); ++j) {
      if (!applies_to(c.assumption, config.systems[j])) continue;
      PlotPanel panel;
      panel.title = fmt::format("system {}: {}", system_number(config.systems[j]), to_string(c.assumption));
      panel.x_label = fmt::format("{}{}", to_string(c.assumption), d.unit.empty() ? "" : " [" + d.unit + "]");
      const auto& rms = even.at_study[j][last_k];
      const auto leader = leader_of(rms);
      for (std::size_t i = 0; i < config.schemes.size(); ++i) {
        // none depends on no assumption and would only squeeze the others.
        if (config.schemes[i] == Scheme::kNone && config.schemes.size() > 1) continue;
        PlotLine line;
        line.name = std::string(to_string(config.schemes[i]));
        line.colour = static_cast<int>(i);
        for (std::size_t q = 0; q < c.values_si.size(); ++q) {
          line.x.push_back(c.values_si[q] * d.per_si);
          line.y.push_back(per_m * c.rms[q][j][last_k][i]);
        }
        if (i == leader)
          for (const Crossing& x : even.crossings)
            if (x.system == config.systems[j] && x.t_s == config.report_times_s[last_k] && x.assumption == c.assumption) {
              const double y = curve_value(c, j, last_k, i, x.value_si);
              if (std::isfinite(y)) line.marks.push_back({x.value_si * d.per_si, per_m * y, per_m * y, per_m * y});
            }
        panel.lines.push_back(std::move(line));
      }
      plot.panels.push_back(std::move(panel));
    }
  }
  return plot;
}

}  // namespace

ReportOutline rank_report_outline() {
  return {"rank", {"ranking.csv", "breakeven.csv", "rank.md", "rank.json"}, {"rank"}};
}

Report rank_report(const StudyConfig& config, const std::vector<SchemeOrder>& orders, const BreakEven& even,
                   LengthUnit unit) {
  RankFiles f;
  const std::string fidelity(to_string(config.fidelity));
  Json orders_json = orders_section(orders, fidelity, unit, f);
  Json crossings_json = crossings_section(even, fidelity, f);
  std::string rank_md = rank_markdown(config, orders, even, fidelity, unit);
  Json rank_json = Json::object();
  rank_json["orders"] = std::move(orders_json);
  rank_json["breakeven"] = std::move(crossings_json);
  Json json = Json::object();
  json["settings"] = settings_json(config);
  json["rank"] = std::move(rank_json);
  std::string json_text = json.dump();
  Report report(rank_report_outline());
  report.file("ranking.csv", std::move(f.ranking_csv))
      .file("breakeven.csv", std::move(f.breakeven_csv))
      .file("rank.md", std::move(rank_md))
      .file("rank.json", std::move(json_text))
      .figure("rank", [plot = rank_plot(config, even, fidelity, unit)] { return render_panel_figure(plot); })
      .shown_file(ReportFormat::kMarkdown, "rank.md")
      .shown_file(ReportFormat::kCsv, "ranking.csv")
      .shown_file(ReportFormat::kJson, "rank.json")
      .summary({fmt::format("insmc rank: fidelity {}, {} samples\n\n{}", fidelity, config.samples,
                            rank_summary(config, orders, even, unit)),
                [](const std::optional<std::string>& out) {
                  return full_tables_line("rank", {"rank.md", "ranking.csv", "breakeven.csv"}, out);
                }});
  return report;
}

}  // namespace insmc::mc
