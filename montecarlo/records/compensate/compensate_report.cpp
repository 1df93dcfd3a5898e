#include "montecarlo/records/compensate/compensate_report.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lib/common/assert.h"
#include "lib/units/units.h"
#include "montecarlo/records/runs/files/site_values.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/markdown.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::compensate {
namespace {

/// Units drawn in one panel at most: the palette's distinct colours.
constexpr std::size_t kMaxUnitsPerPanel = 8;

std::string t_min_text(double t_s) { return mc::format_number(std::round(t_s / 60.0 * 1e6) / 1e6); }
std::string nmi_text(double m) { return fmt::format("{:.3f}", m / kNmiToM); }
const char* axis_name(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

mc::Json vec_json(const Vec3& v) {
  mc::Json j = mc::Json::array();
  for (int a = 0; a < 3; ++a) j.push_back(v[a]);
  return j;
}

mc::Json site_json(const UnitRecords& r) {
  mc::Json j = mc::Json::object();
  j["system"] = system_number(r.site.system);
  j["values"] = runs::site_values_json(r.site_values);
  j["filter_interval_used_s"] = r.site.filter_interval_s;
  j["fitted_terms"] = r.site.estimators->fitted_terms;
  return j;
}

/// A length in the user's unit, to the digits that matter at these sizes.
std::string length_text(double m, mc::LengthUnit u) {
  const double v = m * mc::length_factor(u);
  return u == mc::LengthUnit::kNauticalMile ? fmt::format("{:.3f}", v) : fmt::format("{:.1f}", v);
}

/// Why a unit gets no navigation numbers: its test rows do not fit the
/// model that every predicted position error rests on.
std::string misfit_reason(const UnitResult& u) {
  return fmt::format("the test rows do not fit the model (chi-square {:.4g} over {} rows, p = {:.3g} < {:g}): a position "
                     "error predicted from it would be a number without meaning",
                     u.consistency_chi2, u.consistency_dof, u.consistency_p, kInconsistentP);
}

/// The schemes meeting every limit, in registry order ("none" when none does).
std::string passing_schemes(const UnitResult& u) {
  std::string s;
  for (const SchemeAgainstLimits& a : u.against_limits)
    if (a.meets_every_limit()) s += (s.empty() ? "" : ", ") + std::string(to_string(a.scheme));
  return s.empty() ? "none" : s;
}

/// The recommended scheme held against the limits (with limits, rows that fit).
const SchemeAgainstLimits& chosen_against_limits(const UnitResult& u) {
  for (const SchemeAgainstLimits& a : u.against_limits)
    if (a.scheme == u.recommended) return a;
  INSMC_ASSERT(false, "scheme {} not held against the limits", to_string(u.recommended));
  return u.against_limits.front();
}

std::string verdict_word(const UnitResult& u) {
  switch (u.choice) {
    case SchemeChoice::kNotChosen: return "NO-GO (test rows do not fit the model)";
    case SchemeChoice::kNoneMeetsTheLimits: return "NO-GO (no scheme meets every limit)";
    case SchemeChoice::kMostMarginOverLimits: return "GO";
    case SchemeChoice::kLeastRmsAtFlightTime: break;
  }
  return "no limits given";
}

/// One line per unit before the detail: what a fleet's test campaign needs
/// on one screen. Without limits the scheme is chosen at the flight time and
/// its RMS there is shown; with limits, the chosen scheme's worst limit
/// (the one that decided) and the schemes that meet every limit.
std::string rollup_markdown(const CompensateResult& result, const CompensateOptions& options) {
  if (result.units.empty()) return "";
  const std::string unit = mc::length_suffix(options.units);
  const bool limits = !options.limits.empty();
  mc::Table t = limits ? mc::Table({"run", "scheme to use", fmt::format("its worst limit: RMS ({}) of limit", unit), "P(exceed)",
                            "schemes meeting every limit", "verdict"})
                   : mc::Table({"run", "scheme to use",
                            fmt::format("horizontal RMS at {} min ({})", t_min_text(options.flight_time_s), unit),
                            "ahead of the runner-up", "verdict"});
  int go = 0;
  for (const UnitResult& u : result.units) {
    go += u.go;
    if (u.choice == SchemeChoice::kNotChosen) {
      std::vector<std::string> row = {std::to_string(u.run), "-",
                                      fmt::format("not given: test rows do not fit the model (p = {:.2g})", u.consistency_p)};
      row.resize(limits ? 5 : 4, "-");
      row.push_back(verdict_word(u));
      t.add_row(row);
    } else if (limits) {
      const LimitCheck& w = chosen_against_limits(u).worst();
      t.add_row({std::to_string(u.run),
                 u.choice == SchemeChoice::kNoneMeetsTheLimits ? fmt::format("no scheme (closest: {})", to_string(u.recommended))
                                                               : std::string(to_string(u.recommended)),
                 fmt::format("{} of {}", length_text(w.rms_m, options.units), w.limit.text), fmt::format("{:.2g}", w.probability),
                 passing_schemes(u), verdict_word(u)});
    } else {
      t.add_row({std::to_string(u.run), std::string(to_string(u.recommended)),
                 length_text(u.recommended_rms_m, options.units),
                 u.runner_up ? fmt::format("{} {} over {}", length_text(u.margin_m, options.units), unit,
                                           to_string(*u.runner_up))
                             : "-",
                 verdict_word(u)});
    }
  }
  const int n = static_cast<int>(result.units.size());
  std::string beyond;
  for (const UnitResult& u : result.units)
    if (u.beyond_linear_level()) beyond += (beyond.empty() ? "" : ", ") + std::to_string(u.run);
  if (!beyond.empty())
    beyond = fmt::format(" The test rows of run(s) {} fit the model only with more of its model-error allowance than "
                         "rows of the linear level reach (p < {:g} there): a sign of an effect the model lacks (each "
                         "run's section gives the chi-square).",
                         beyond, kInconsistentP);
  return fmt::format("## The units at a glance\n\n{}\n{} of {} unit(s) go{}.{} The detail of each follows.\n\n",
                     mc::render_markdown(t), go, n,
                     !limits ? " (no --limit given: only a unit whose test rows do not fit the model is no-go)"
                             : fmt::format(" (go: some scheme exceeds each --limit with probability at most {:g}; of "
                                           "those, the one whose worst limit has the largest ratio limit / RMS is used)",
                                           options.risk),
                     beyond);
}

/// The site's values with their sources, and the statements about the records.
std::string site_markdown(const UnitRecords& rec) {
  std::string md;
  mc::Table site({"key", "value", "source", "reason"});
  for (const runs::SiteValue& v : rec.site_values) site.add_row({v.key, mc::format_number(v.value), v.source, v.reason});
  md += "## The site and its test run\n\n" + mc::render_markdown(site) + "\n";
  for (const std::string& s : rec.statements) md += "- " + s + "\n";
  if (!rec.statements.empty()) md += "\n";
  return md;
}

/// What the test run separates: each coefficient's sigma after T, 2T, 4T
/// (markdown into `md`; returns its JSON).
mc::Json identifiability_section(const CompensateResult& result, const UnitRecords& rec, std::string& md) {
  mc::Table t({"coefficient", "mixes (share of its spread)", "prior sigma", "sigma at T", "at 2T", "at 4T"});
  mc::Json ident = mc::Json::array();
  for (const Identifiability& e : result.identifiability) {
    std::string mixes;
    mc::Json m = mc::Json::array();
    for (const auto& [name, share] : e.mixes) {
      mixes += fmt::format("{}{} {:.0f} %", mixes.empty() ? "" : ", ", name, 100 * share);
      mc::Json j = mc::Json::object();
      j["uncertainty"] = name;
      j["share"] = share;
      m.push_back(std::move(j));
    }
    std::vector<std::string> row = {e.name, mixes, fmt::format("{:.3g}", e.prior_sigma)};
    mc::Json sig = mc::Json::array();
    for (const auto& [T, sigma] : e.sigma_by_duration) {
      row.push_back(fmt::format("{:.3g}", sigma));
      mc::Json j = mc::Json::object();
      j["test_duration_s"] = T;
      j["sigma"] = sigma;
      sig.push_back(std::move(j));
    }
    t.add_row(row);
    mc::Json j = mc::Json::object();
    j["name"] = e.name;
    j["mixes"] = std::move(m);
    j["prior_sigma"] = e.prior_sigma;
    j["sigma_by_test_duration"] = std::move(sig);
    ident.push_back(std::move(j));
  }
  md += "## What the test run separates\n\n" + mc::render_markdown(t) +
        fmt::format("\nEach coefficient of (3.29b-d) is a sum over Table 3.1's uncertainties (4.10); its sigma after a "
                    "test run of T = {:g} min, and of 2T and 4T with as many filter windows, is that of the best "
                    "linear estimate from the test rows (no data needed). A coefficient whose sigma stays near its "
                    "prior spread is not separated by this test; (4.6) gives the pulse-count limit.\n\n",
                    rec.site.test_duration_s / 60.0);
  return ident;
}

/// A unit's estimates: rows of estimates.csv, markdown into `md`; returns their JSON.
/// An estimate's unit in the report: U2..U4 are angles (rad inside), shown
/// in arcsec with the paper's feet (Table 3.1's unit of tilts) and in µrad
/// otherwise; df_T in µg (Table 3.1's unit of accelerometer errors).
struct DisplayUnit {
  std::string name;
  double per_si;
};
DisplayUnit display_unit(const UnitEstimate& e, mc::LengthUnit units) {
  if (e.unit == "rad") return units == mc::LengthUnit::kFoot ? DisplayUnit{"arcsec", 1.0 / kArcsecToRad} : DisplayUnit{"urad", 1.0 / kUradToRad};
  if (e.unit == "m/s^2") return {"ug", 1.0 / kUgToMps2};
  return {e.unit, 1.0};
}

mc::Json estimates_section(const UnitResult& u, const std::string& run, mc::LengthUnit units, mc::Table& estimates, std::string& md) {
  md += "### Estimates\n\n";
  mc::Table est_md({"coefficient", "this unit", "sigma", "prior sigma", "report's estimator", "unit", "resolved"});
  mc::Json est_json = mc::Json::array();
  for (const UnitEstimate& e : u.estimates) {
    const std::string report = e.report_estimator ? mc::format_number(*e.report_estimator) : "";
    estimates.add_row({run, e.name, mc::format_number(e.value), mc::format_number(e.sigma), mc::format_number(e.prior_sigma),
                       report, e.unit, e.resolved() ? "yes" : "no"});
    const DisplayUnit d = display_unit(e, units);
    est_md.add_row({e.name, fmt::format("{:.4g}", d.per_si * e.value), fmt::format("{:.3g}", d.per_si * e.sigma),
                    fmt::format("{:.3g}", d.per_si * e.prior_sigma),
                    e.report_estimator ? fmt::format("{:.4g}", d.per_si * *e.report_estimator) : "-", d.name,
                    e.resolved() ? "yes" : "no"});
    mc::Json j = mc::Json::object();
    j["name"] = e.name;
    j["value"] = e.value;
    j["sigma"] = e.sigma;
    j["unit"] = e.unit;
    j["prior_sigma"] = e.prior_sigma;
    if (e.report_estimator) j["report_estimator"] = *e.report_estimator;
    j["resolved"] = e.resolved();
    est_json.push_back(std::move(j));
  }
  md += mc::render_markdown(est_md) +
        "\nU2..U4 are the report's coefficients (3.29b-d) of this unit, angles (each term a tilt, δf/g or a drift over "
        "ω_ie; rad in estimates.csv), df_T its accelerometer output error at T (m/s^2 in estimates.csv): "
        "their best linear estimate from the test rows and its error's sigma; `resolved` when the test run "
        "halves the population's spread. The report's estimators (4.8b, c), (5.10) are what the schemes apply.\n\n";
  return est_json;
}

/// The compensation each scheme applies and its envelope: rows of
/// compensation.csv and envelope.csv, markdown into `md`; returns their JSON.
mc::Json schemes_section(const UnitResult& u, const UnitRecords& rec, const std::string& run, mc::Table& compensation,
                     mc::Table& envelope, std::string& md) {
  md += "### The compensation each scheme applies\n\n";
  mc::Table comp_md({"scheme", "ready (min)", "step at point 2 (ug)", "ramp (ug/min)", "torquer rates (meru)", "also"});
  mc::Json schemes = mc::Json::array();
  for (const SchemePrediction& p : u.schemes) {
    const std::string name(to_string(p.scheme));
    const SchemeCompensation& c = p.compensation;
    const auto list = [](const Vec3& v, double scale) {
      return fmt::format("{:.4g}, {:.4g}, {:.4g}", v[0] / scale, v[1] / scale, v[2] / scale);
    };
    std::string also;
    if (c.realigns) also += "realign; ";
    if (c.resets_at_test_end) also += "reset velocity and position at T; ";
    if (c.from_alignment_data) also += "from the alignment phase's torquer commands and accelerometer outputs (not in the records: modelled); ";
    comp_md.add_row({name, t_min_text(p.ready_time_s), list(c.step_mps2, kUgToMps2), list(c.ramp_mps3, kUgToMps2 / 60.0),
                     list(c.torquer_radps, kMeruToRadps), also});
    for (int a = 0; a < 3; ++a) {
      compensation.add_row({run, name, "step", axis_name(a), mc::format_number(c.step_mps2[a]), "m/s^2"});
      compensation.add_row({run, name, "ramp", axis_name(a), mc::format_number(c.ramp_mps3[a]), "m/s^3"});
      compensation.add_row({run, name, "torquer_rate", axis_name(a), mc::format_number(c.torquer_radps[a]), "rad/s"});
    }
    mc::Json cj = mc::Json::object();
    cj["step_mps2"] = vec_json(c.step_mps2);
    cj["ramp_mps3"] = vec_json(c.ramp_mps3);
    cj["torquer_radps"] = vec_json(c.torquer_radps);
    cj["realigns"] = c.realigns;
    cj["resets_at_test_end"] = c.resets_at_test_end;
    cj["from_alignment_data"] = c.from_alignment_data;
    mc::Json env = mc::Json::array();
    for (const UnitPositionError& e : p.envelope) {
      for (int a = 0; a <= 3; ++a) {
        const bool h = a == 3;
        const double unit_rms = h ? e.unit_horizontal_rms_m() : e.unit_rms_m(a);
        const double pop_rms = h ? e.population_horizontal_rms_m() : e.population_rms_m(a);
        const std::string axis = h ? "horizontal" : axis_name(a);
        // A unit whose rows do not fit the model gets no numbers of its own
        // (empty cells, no keys): they would mean nothing.
        const bool fits = u.fits_model();
        envelope.add_row({run, name, t_min_text(e.t_s), axis, h || !fits ? "" : mc::format_number(e.mean_m[a]),
                          fits ? mc::format_number(unit_rms) : "", mc::format_number(pop_rms)});
        mc::Json ej = mc::Json::object();
        ej["system"] = system_number(rec.site.system);
        ej["axis"] = axis;
        ej["t_min"] = e.t_s / 60.0;
        if (fits) ej["rms_m"] = unit_rms;
        ej["population_rms_m"] = pop_rms;
        if (!h && fits) ej["mean_m"] = e.mean_m[a];
        env.push_back(std::move(ej));
      }
    }
    mc::Json sj = mc::Json::object();
    sj["scheme"] = name;
    sj["ready_time_s"] = p.ready_time_s;
    sj["compensation"] = std::move(cj);
    sj["envelope"] = std::move(env);
    schemes.push_back(std::move(sj));
  }
  md += mc::render_markdown(comp_md) +
        "\nPer axis x, y, z of the platform frame a'. The step and ramp act from the scheme's start; torquer rates "
        "from the switch-over (5.1.2, combined).\n\n";
  return schemes;
}

/// A unit's position error at the report times against the population's.
std::string envelope_markdown(const UnitResult& u, const CompensateOptions& options) {
  std::string md;
  md += "### Position error after each scheme: this unit and the population\n\n";
  if (!u.fits_model())
    return md + "Not given: " + misfit_reason(u) + ". `insmc gap` on these records says where and which effect.\n\n";
  mc::Table env_md({"scheme", "t (min)", "this unit: horizontal RMS (m)", "(n.mi.)", "population (m)", "this unit x, y, z RMS (m)"});
  for (const SchemePrediction& p : u.schemes)
    for (const UnitPositionError& e : p.envelope)
      if (is_report_time(e.t_s, options))
        env_md.add_row({std::string(to_string(p.scheme)), t_min_text(e.t_s), fmt::format("{:.1f}", e.unit_horizontal_rms_m()),
                        nmi_text(e.unit_horizontal_rms_m()), fmt::format("{:.1f}", e.population_horizontal_rms_m()),
                        fmt::format("{:.1f}, {:.1f}, {:.1f}", e.unit_rms_m(0), e.unit_rms_m(1), e.unit_rms_m(2))});
  md += mc::render_markdown(env_md) +
        "\nThis unit's RMS is over what its test run leaves unknown (the run model conditioned on its data); the "
        "population's over Table 3.1's units with the same test run. Both are exact for the linear level: no "
        "sampling, so no interval. Every 3 min in envelope.csv.\n\n";
  return md;
}

mc::Json check_json(const LimitCheck& c) {
  mc::Json j = mc::Json::object();
  j["limit"] = c.limit.text;
  j["component"] = std::string(to_string(c.limit.component));
  j["t_min"] = c.limit.t_s / 60.0;
  j["limit_m"] = c.limit.limit_m;
  j["rms_m"] = c.rms_m;
  j["probability"] = c.probability;
  j["risk"] = c.risk;
  j["within"] = c.within();
  return j;
}

/// Every scheme against every limit and the verdict: markdown into `md`;
/// returns the schemes' JSON (`against_limits`).
mc::Json verdict_section(const UnitResult& u, const CompensateOptions& options, std::string& md) {
  mc::Json against = mc::Json::array();
  if (u.choice == SchemeChoice::kNotChosen) {
    md += "### Verdict: NO-GO (the test rows do not fit the model)\n\nNo scheme is chosen and no limit is evaluated: " +
          misfit_reason(u) + ".\n\n";
    return against;
  }
  if (u.against_limits.empty()) return against;
  std::vector<std::string> head = {"scheme"};
  for (const PositionLimit& l : options.limits)
    head.push_back(fmt::format("{}: RMS ({}), P(exceed)", l.text, mc::length_suffix(options.units)));
  head.push_back("meets every limit");
  head.push_back("worst ratio limit / RMS");
  mc::Table lim(head);
  for (const SchemeAgainstLimits& a : u.against_limits) {
    std::vector<std::string> row = {std::string(to_string(a.scheme)) +
        (a.scheme != u.recommended ? "" : u.choice == SchemeChoice::kMostMarginOverLimits ? " (chosen)" : " (closest)")};
    mc::Json checks = mc::Json::array();
    for (const LimitCheck& c : a.checks) {
      row.push_back(fmt::format("{}, {:.3g}{}", length_text(c.rms_m, options.units), c.probability,
                                c.within() ? "" : " (fails)"));
      checks.push_back(check_json(c));
    }
    row.push_back(a.meets_every_limit() ? "yes" : "no");
    row.push_back(fmt::format("{:.3g}", a.worst().ratio()));
    lim.add_row(row);
    mc::Json j = mc::Json::object();
    j["scheme"] = std::string(to_string(a.scheme));
    j["meets_every_limit"] = a.meets_every_limit();
    j["worst_ratio"] = a.worst().ratio();
    j["checks"] = std::move(checks);
    against.push_back(std::move(j));
  }
  const SchemeAgainstLimits& chosen = chosen_against_limits(u);
  const std::string heading =
      u.choice == SchemeChoice::kMostMarginOverLimits
          ? fmt::format("### Verdict: GO with scheme {}", to_string(u.recommended))
          : fmt::format("### Verdict: NO-GO: no scheme meets every limit (closest: {}, worst P(exceed) {:.3g})",
                        to_string(u.recommended), chosen.worst_probability());
  md += heading + "\n\n" + mc::render_markdown(lim) +
        fmt::format("\nA scheme meets a limit when the limit is exceeded with probability at most {:g} (--risk), the "
                    "position error taken Gaussian with this unit's mean and covariance at the limit's time. Schemes "
                    "meeting every limit: {}. Of those the one used is the one whose worst limit has the largest ratio "
                    "limit / RMS (the most margin); go when there is one. --flight-time does not choose when limits are "
                    "given: it only adds its time to the tables.\n\n",
                    options.risk, passing_schemes(u));
  return against;
}

/// Each unit's horizontal RMS after each scheme against the population's,
/// one panel per scheme, with the horizontal limits. Beyond 8 units (the
/// palette's distinct colours) the units are drawn in groups of 8, a panel
/// per scheme and group (small multiples): every unit is drawn. A unit whose
/// test rows do not fit the model has no RMS to draw; the title says which.
mc::PanelFigure compensate_plot(const CompensateResult& result, const CompensateOptions& options, const std::string& source) {
  mc::PanelFigure plot;
  plot.stem = "compensate";
  const double per_m = mc::length_factor(options.units);
  std::vector<std::size_t> drawn;
  std::string misfit;
  for (std::size_t k = 0; k < result.units.size(); ++k)
    if (result.units[k].fits_model()) drawn.push_back(k);
    else misfit += (misfit.empty() ? "" : ", ") + std::to_string(result.units[k].run);
  const std::size_t groups = (drawn.size() + kMaxUnitsPerPanel - 1) / kMaxUnitsPerPanel;
  plot.title = fmt::format("{}: horizontal RMS of each unit after each scheme, against the population{}{}", source,
                           groups > 1 ? fmt::format(" ({} units, at most {} a panel: a panel per scheme and group)", drawn.size(), kMaxUnitsPerPanel) : "",
                           misfit.empty() ? "" : fmt::format("; not drawn (test rows do not fit the model): run {}", misfit));
  plot.x_label = "time on the scheme's clock [min]";
  plot.y_label = fmt::format("horizontal RMS [{}]", mc::length_suffix(options.units));
  plot.marked_x = {42, 63, 84};
  if (result.units.empty()) return plot;
  const std::size_t schemes = result.units.front().schemes.size();
  plot.columns = 3;
  for (std::size_t g = 0; g < std::max<std::size_t>(groups, 1); ++g)
    for (std::size_t s = 0; s < schemes; ++s) {
      mc::PlotPanel panel;
      panel.title = std::string(to_string(result.units.front().schemes[s].scheme));
      if (groups > 1)
        panel.title += fmt::format(", runs {}-{}", result.units[drawn[g * kMaxUnitsPerPanel]].run,
                                   result.units[drawn[std::min(drawn.size(), (g + 1) * kMaxUnitsPerPanel) - 1]].run);
      mc::PlotLine pop;
      pop.name = "population";
      pop.thin = true;
      for (const UnitPositionError& e : result.units.front().schemes[s].envelope) {
        pop.x.push_back(e.t_s / 60.0);
        pop.y.push_back(per_m * e.population_horizontal_rms_m());
      }
      panel.lines.push_back(pop);
      // The limits the RMS is held against (horizontal ones; a limit on
      // one axis is not a horizontal RMS).
      for (const PositionLimit& l : options.limits)
        if (l.component == PositionLimit::Component::kHorizontal)
          panel.limits.push_back({per_m * l.limit_m,
                                  fmt::format("limit {} at {:g} min", l.text.substr(l.text.find('=') + 1), l.t_s / 60),
                                  l.t_s / 60});
      for (std::size_t i = g * kMaxUnitsPerPanel; i < drawn.size() && i < (g + 1) * kMaxUnitsPerPanel; ++i) {
        const UnitResult& u = result.units[drawn[i]];
        mc::PlotLine line;
        line.name = fmt::format("unit (run {})", u.run);
        line.colour = static_cast<int>(i % kMaxUnitsPerPanel);
        for (const UnitPositionError& e : u.schemes[s].envelope) {
          line.x.push_back(e.t_s / 60.0);
          line.y.push_back(per_m * e.unit_horizontal_rms_m());
        }
        panel.lines.push_back(std::move(line));
      }
      plot.panels.push_back(std::move(panel));
    }
  return plot;
}

std::string choice_name(SchemeChoice c) {
  switch (c) {
    case SchemeChoice::kLeastRmsAtFlightTime: return "least_rms_at_flight_time";
    case SchemeChoice::kMostMarginOverLimits: return "most_margin_over_limits";
    case SchemeChoice::kNoneMeetsTheLimits: return "none_meets_the_limits";
    case SchemeChoice::kNotChosen: break;
  }
  return "not_chosen_rows_do_not_fit";
}

/// The decision in words, with the numbers it rests on.
std::string scheme_to_use_summary(const UnitResult& u, const CompensateOptions& options) {
  const std::string unit = mc::length_suffix(options.units);
  switch (u.choice) {
    case SchemeChoice::kNotChosen: return "NO-GO: no scheme chosen, " + misfit_reason(u);
    case SchemeChoice::kLeastRmsAtFlightTime:
      return fmt::format("use {} (least horizontal RMS at {} min: {} {}{}); no limits given", to_string(u.recommended),
                         t_min_text(options.flight_time_s), length_text(u.recommended_rms_m, options.units), unit,
                         u.runner_up ? fmt::format(", {} {} ahead of {}", length_text(u.margin_m, options.units), unit,
                                                   to_string(*u.runner_up))
                                     : "");
    case SchemeChoice::kMostMarginOverLimits:
    case SchemeChoice::kNoneMeetsTheLimits: break;
  }
  const LimitCheck& w = chosen_against_limits(u).worst();
  const std::string worst = fmt::format("its worst limit {}: RMS {} {}, P(exceed) {:.3g}, ratio limit / RMS {:.3g}",
                                        w.limit.text, length_text(w.rms_m, options.units), unit, w.probability, w.ratio());
  if (u.choice == SchemeChoice::kNoneMeetsTheLimits)
    return fmt::format("NO-GO: no scheme meets every limit; closest {} ({})", to_string(u.recommended), worst);
  return fmt::format("GO with {} ({}); meeting every limit: {}", to_string(u.recommended), worst, passing_schemes(u));
}

std::string scheme_to_use_line(const UnitResult& u, const CompensateOptions& options) {
  if (u.choice == SchemeChoice::kNotChosen) return "";
  return "**" + scheme_to_use_summary(u, options) + ".**\n\n";
}

}  // namespace

mc::ReportOutline compensate_report_outline() {
  return {"compensate",
          {"compensate.md", "estimates.csv", "compensation.csv", "envelope.csv", "compensate.json"},
          {"compensate"}};
}

mc::Report compensate_report(const CompensateResult& result, const CompensateOptions& options, const std::string& source) {
  const UnitRecords& rec = result.records;
  mc::Table estimates({"run", "name", "value", "sigma", "prior_sigma", "report_estimator", "unit", "resolved"});
  mc::Table compensation({"run", "scheme", "quantity", "axis", "value", "unit"});
  mc::Table envelope({"run", "scheme", "t_min", "axis", "unit_mean_m", "unit_rms_m", "population_rms_m"});
  std::string md = fmt::format("# insmc compensate: {}\n\n", source);
  md += fmt::format(
      "System {}, test run T = {:g} min, filter interval {:g} s, estimators fit {} (4.7), (4.8), (4.4). Flight time "
      "{} min on each scheme's clock; {}.\n\n",
      system_number(rec.site.system), rec.site.test_duration_s / 60.0, rec.site.filter_interval_s,
      rec.site.estimators->fitted_terms, t_min_text(options.flight_time_s),
      options.limits.empty() ? "the scheme to use is the one with the least horizontal RMS there"
                             : "the scheme to use is chosen by the limits (among the schemes meeting every limit, the "
                               "one whose worst limit has the largest ratio limit / RMS), not at the flight time");
  md += rollup_markdown(result, options);
  md += site_markdown(rec);
  mc::Json identifiability_json = identifiability_section(result, rec, md);
  mc::Json units = mc::Json::array();
  for (const UnitResult& u : result.units) {
    const std::string run = std::to_string(u.run);
    md += fmt::format("## Run {}\n\n", run);
    const double linear_p = u.consistency_band.linear_p(u.consistency_chi2);
    md += fmt::format("The test rows against the model: chi-square {:.6g} over {} rows, p = {:.3g} against the model "
                      "with its whole model-error allowance (rows using all of it would give {} ± {:.0f}); rows of the linear "
                      "level alone give {:.0f} ± {:.0f}, p = {:.3g}{}\n\n",
                      u.consistency_chi2, u.consistency_dof, u.consistency_p, u.consistency_dof,
                      std::sqrt(2.0 * u.consistency_dof), u.consistency_band.linear_mean,
                      u.consistency_band.linear_sd, linear_p,
                      !u.fits_model()
                          ? fmt::format(". **They do not fit the model (p < {:g})**: what follows assumes it, and no "
                                        "verdict is go; `insmc gap` on these records says where and why",
                                        kInconsistentP)
                      : u.beyond_linear_level()
                          ? fmt::format(". **They use more of the model-error allowance than the linear level leaves "
                                        "room for (p < {:g} there)**: the allowance stands for the truth's "
                                        "second-order terms, which simulated truth units hardly show on a test run, "
                                        "so this is more likely an effect the model lacks; the predictions below "
                                        "stand, and `insmc gap` on these records says where",
                                        kInconsistentP)
                          : "");
    mc::Json est_json = estimates_section(u, run, options.units, estimates, md);
    mc::Json schemes = schemes_section(u, rec, run, compensation, envelope, md);
    md += envelope_markdown(u, options);
    mc::Json against_limits = verdict_section(u, options, md);
    md += scheme_to_use_line(u, options);
    mc::Json uj = mc::Json::object();
    uj["run"] = static_cast<long long>(u.run);
    uj["estimates"] = std::move(est_json);
    uj["schemes"] = std::move(schemes);
    uj["choice"] = choice_name(u.choice);
    if (u.choice != SchemeChoice::kNotChosen) uj["recommended"] = std::string(to_string(u.recommended));
    if (u.runner_up) {
      uj["runner_up"] = std::string(to_string(*u.runner_up));
      uj["margin_m"] = u.margin_m;
    }
    mc::Json consistency = mc::Json::object();
    consistency["chi2"] = u.consistency_chi2;
    consistency["dof"] = u.consistency_dof;
    consistency["p"] = u.consistency_p;
    consistency["linear_level_mean"] = u.consistency_band.linear_mean;
    consistency["linear_level_sd"] = u.consistency_band.linear_sd;
    consistency["linear_level_p"] = u.consistency_band.linear_p(u.consistency_chi2);
    consistency["fits_model"] = u.fits_model();
    uj["consistency"] = std::move(consistency);
    mc::Json verdict = mc::Json::object();
    verdict["go"] = u.go;
    mc::Json checks = mc::Json::array();
    for (const LimitCheck& c : u.checks) checks.push_back(check_json(c));
    verdict["checks"] = std::move(checks);
    if (!u.against_limits.empty()) verdict["schemes"] = std::move(against_limits);
    uj["verdict"] = std::move(verdict);
    units.push_back(std::move(uj));
  }
  bool go = true;
  for (const UnitResult& u : result.units) go = go && u.go;
  mc::Json json = mc::Json::object();
  json["source"] = source;
  json["identifiability"] = std::move(identifiability_json);
  json["site"] = site_json(rec);
  mc::Json statements = mc::Json::array();
  for (const std::string& s : rec.statements) statements.push_back(s);
  json["statements"] = std::move(statements);
  json["flight_time_s"] = options.flight_time_s;
  json["risk"] = options.risk;
  json["units"] = std::move(units);
  json["go"] = go;
  std::string json_text = json.dump(2) + "\n", envelope_csv = render_csv(envelope);

  mc::Report report(compensate_report_outline());
  report.file("compensate.md", std::move(md))
      .file("estimates.csv", render_csv(estimates))
      .file("compensation.csv", render_csv(compensation))
      .file("envelope.csv", std::move(envelope_csv))
      .file("compensate.json", std::move(json_text))
      .figure("compensate", [plot = compensate_plot(result, options, source)] { return render_panel_figure(plot); })
      .shown_file(mc::ReportFormat::kMarkdown, "compensate.md")
      .shown_file(mc::ReportFormat::kCsv, "envelope.csv")
      .shown_file(mc::ReportFormat::kJson, "compensate.json");
  return report;
}

}  // namespace insmc::compensate
