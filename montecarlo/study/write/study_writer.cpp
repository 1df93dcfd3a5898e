#include "montecarlo/study/write/study_writer.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "lib/common/version.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/units/quantity.h"
#include "lib/units/units.h"
#include "montecarlo/study/write/accuracy_cells.h"
#include "montecarlo/study/aggregate/gaussian_cep.h"
#include "montecarlo/study/write/budget_plot.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/study/write/envelope_summary.h"
#include "montecarlo/report/interval_format.h"
#include "montecarlo/report/markdown.h"

namespace insmc::mc {
namespace {

/// Where t = 0 is on a scheme's clock (clock_of), for a plot's panel title.
std::string clock_title(Scheme scheme) {
  const std::string_view clock = clock_of(scheme);
  return clock == "switchover" ? "switch-over" : clock == "realignment" ? "switch-over after the realignment" : "end of the test run";
}

/// The plot line of one scheme (its panel) and system, made on first use.
/// `covariance`: the line of the exact linear-covariance prediction (at
/// `map_fidelity`) beside the Monte Carlo one.
PlotLine& envelope_line(PanelFigure& plot, std::size_t panel, const OutputSpec& spec, bool covariance,
                        Fidelity map_fidelity) {
  if (plot.panels.size() <= panel) plot.panels.resize(panel + 1);
  PlotPanel& p = plot.panels[panel];
  p.title = fmt::format("{} (t = 0: {})", to_string(spec.scheme), clock_title(spec.scheme));
  const std::string name =
      covariance ? fmt::format("system {}, covariance ({})", system_number(spec.system), to_string(map_fidelity))
                 : fmt::format("system {}", system_number(spec.system));
  for (PlotLine& line : p.lines)
    if (line.name == name) return line;
  const bool gyrocompass = spec.system == System::kGyrocompass;
  p.lines.push_back({name, {}, {}, {}, {}, {}, gyrocompass ? 1 : 0, gyrocompass && !covariance, covariance});
  return p.lines.back();
}



std::string fmt_minutes(double t_s) { return format_number(t_s / 60.0); }

int scheme_index(const StudyConfig& c, Scheme s) {
  for (size_t i = 0; i < c.schemes.size(); ++i)
    if (c.schemes[i] == s) return static_cast<int>(i);
  return 0;
}

std::vector<std::string> envelope_header(LengthUnit u) {
  // fmt, not string operator+: GCC 12 -O3 raises a false -Wrestrict on the latter.
  const std::string u_ = length_suffix(u);
  std::vector<std::string> header = {"scheme", "system", "clock", "axis", "t_min", "n"};
  for (const char* q : {"rms", "rms_lo", "rms_hi", "mean", "std", "min", "max", "p95"})
    header.push_back(fmt::format("{}_{}", q, u_));
  header.push_back("ready_time_min");
  for (std::string& column : accuracy_header(u)) header.push_back(std::move(column));
  return header;
}

std::string rms_interval_column(LengthUnit u, double confidence) {
  return fmt::format("RMS [{}] ± half-width ({}% CI)", length_suffix(u), format_number(100 * confidence));
}

/// envelope.md's header: the columns of envelope.csv for people, the RMS
/// with its interval in one cell.
std::vector<std::string> readable_header(LengthUnit u, double confidence) {
  const std::string u_ = length_suffix(u);
  std::vector<std::string> header = {"scheme", "system", "clock", "axis", "t_min", "n",
                                     rms_interval_column(u, confidence)};
  for (const char* q : {"mean", "std", "min", "max", "p95"}) header.push_back(fmt::format("{} [{}]", q, u_));
  header.emplace_back("ready [min]");
  for (std::string& column : readable_accuracy_header(u)) header.push_back(std::move(column));
  return header;
}

/// A row's statistics other than the RMS have no interval of their own;
/// they come from the same samples, so the RMS interval's place is the
/// precision they are printed to as well.
std::string at_rms_precision(double x, std::optional<int> place) {
  return place ? format_at_place(x, *place) : format_significant(x, 6);
}

/// The summary's figures of one row's metrics, in the printed unit.
AccuracyFigures figures_of(const HorizontalAccuracy& a, double k) {
  const auto half = [](const QuantileEstimate& e) { return 0.5 * (e.hi - e.lo); };
  return {k * a.cep50_m.value, k * half(a.cep50_m), k * a.drms2_m.value, k * half(a.drms2_m),
          mps_to_nmiph(a.radial_rate_mps.value), mps_to_nmiph(half(a.radial_rate_mps))};
}

/// The accuracy metrics of the covariance level: 2DRMS = 2·RMS exactly; CEP50
/// and CEP95 of the Gaussian with the output's exact mean and covariance
/// (gaussian_cep.h); the radial rate CEP50/t (none at t = 0).
struct CovarianceAccuracy {
  double cep50_m = 0, cep95_m = 0, drms2_m = 0;
  std::optional<double> rate_nmiph;
};

CovarianceAccuracy covariance_accuracy(const StudyMap& map, std::size_t output, double t_s) {
  const HorizontalMoments& h = map.predicted_horizontal(output);
  CovarianceAccuracy a;
  a.cep50_m = gaussian_cep(h.mean, h.covariance, 0.5);
  a.cep95_m = gaussian_cep(h.mean, h.covariance, 0.95);
  a.drms2_m = 2 * map.predicted_rms()[output];
  if (t_s > 0) a.rate_nmiph = mps_to_nmiph(a.cep50_m / t_s);
  return a;
}

}  // namespace

EnvelopeFiles render_envelope(const StudyConfig& c, const StudyLayout& l, const StudyMap& map,
                              const StudyAccumulator& acc, LengthUnit unit) {
  const double k = length_factor(unit);
  Table report(envelope_header(unit)), grid(envelope_header(unit)), readable(readable_header(unit, c.confidence));
  std::vector<std::string> full_header = {"scheme", "system", "axis", "t_min", rms_interval_column(unit, c.confidence), "n"};
  for (std::string& column : readable_accuracy_header(unit)) full_header.push_back(std::move(column));
  Table full(full_header);
  std::vector<HorizontalPoint> horizontal;
  EnvelopeFiles f;
  f.envelope_json = Json::array();
  PanelFigure plot;
  // The accuracy figures select order statistics from each kept output's
  // values (as many as the samples): the outputs side by side on the run's
  // threads.
  std::vector<std::optional<HorizontalAccuracy>> accuracies(l.outputs.size());
  tbb::task_arena arena(c.threads > 0 ? c.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, l.outputs.size(), [&](std::size_t o) {
      accuracies[o] = acc.accuracy(l, o, acc.outputs()[o].summarize(c.confidence), c.confidence);
    });
  });
  for (size_t o = 0; o < l.outputs.size(); ++o) {
    const OutputSpec& spec = l.outputs[o];
    const OutputSummary s = acc.outputs()[o].summarize(c.confidence);
    const double t = l.times_s[spec.time_index];
    const std::optional<HorizontalAccuracy>& accuracy = accuracies[o];
    std::vector<std::string> row = {std::string(to_string(spec.scheme)), std::to_string(system_number(spec.system)),
                                    std::string(clock_of(spec.scheme)), std::string(to_string(spec.axis)),
                                    fmt_minutes(t), std::to_string(s.n), format_number(k * s.rms),
                                    format_number(k * s.rms_lo), format_number(k * s.rms_hi),
                                    format_number(k * s.mean), format_number(k * s.std), format_number(k * s.min),
                                    format_number(k * s.max), format_number(k * s.p95_abs),
                                    format_number(map.ready_time_s(scheme_index(c, spec.scheme)) / 60.0)};
    for (std::string& cell : accuracy_cells(accuracy, unit)) row.push_back(std::move(cell));
    if (l.is_grid_time[spec.time_index]) grid.add_row(row);
    if (l.is_report_time[spec.time_index]) {
      report.add_row(row);
      const double half = 0.5 * k * (s.rms_hi - s.rms_lo);
      const std::string rms = format_with_interval(k * s.rms, half);
      const std::optional<int> place = interval_place(half);
      std::vector<std::string> full_row = {row[0], row[1], row[3], row[4], rms, std::to_string(s.n)};
      for (std::string& cell : readable_accuracy_cells(accuracy, unit)) full_row.push_back(std::move(cell));
      full.add_row(std::move(full_row));
      std::vector<std::string> readable_row = {row[0], row[1], row[2], row[3], row[4], row[5], rms,
                                               at_rms_precision(k * s.mean, place), at_rms_precision(k * s.std, place),
                                               at_rms_precision(k * s.min, place), at_rms_precision(k * s.max, place),
                                               at_rms_precision(k * s.p95_abs, place), row[14]};
      for (std::string& cell : readable_accuracy_cells(accuracy, unit)) readable_row.push_back(std::move(cell));
      readable.add_row(std::move(readable_row));
      if (spec.axis == Axis::kHorizontal)
        horizontal.push_back({row[0], row[2], system_number(spec.system), t / 60.0, k * s.rms, half,
                              map.ready_time_s(scheme_index(c, spec.scheme)) / 60.0,
                              accuracy ? std::optional(figures_of(*accuracy, k)) : std::nullopt});
      Json j = output_row_json(spec, t, s, map.ready_time_s(scheme_index(c, spec.scheme)));
      add_accuracy_json(j, accuracy);
      f.envelope_json.push_back(j);
    }
    if (spec.axis == Axis::kHorizontal && (l.is_grid_time[spec.time_index] || l.is_report_time[spec.time_index])) {
      PlotLine& line = envelope_line(plot, scheme_index(c, spec.scheme), spec, false, c.map_fidelity());
      if (l.is_grid_time[spec.time_index]) {
        line.x.push_back(t / 60.0);
        line.y.push_back(k * s.rms);
        line.lo.push_back(k * s.rms_lo);
        line.hi.push_back(k * s.rms_hi);
        PlotLine& predicted = envelope_line(plot, scheme_index(c, spec.scheme), spec, true, c.map_fidelity());
        predicted.x.push_back(t / 60.0);
        predicted.y.push_back(k * map.predicted_rms()[o]);
      }
      if (l.is_report_time[spec.time_index]) line.marks.push_back({t / 60.0, k * s.rms, k * s.rms_lo, k * s.rms_hi});
    }
  }
  f.envelope_csv = render_csv(report);
  f.envelope_grid_csv = render_csv(grid);
  f.envelope_md = fmt::format(
      "# insmc run: RMS position error\n\n{} samples, seed {}, fidelity {}, latitude {} deg; "
      "confidence intervals {}% (fourth-moment delta method on the log scale, Student's t). Each row is printed "
      "to the second significant figure of its RMS interval's half-width; envelope.csv has every number at full "
      "precision.\n\n{}",
      c.samples, c.seed, to_string(c.fidelity), format_number(c.model.latitude_rad / kDegToRad),
      format_number(100 * c.confidence), render_markdown(readable));
  f.full_text = render_markdown(full);
  f.summary_text = render_horizontal_summary(
      horizontal, fmt::format("Horizontal RMS position error [{}] ± half its {}% interval; CEP50 (median radial "
                              "error), 2DRMS (2·RMS), CEP/t (CEP50 rate) from the samples; ready: minutes to flight.",
                              length_suffix(unit), format_number(100 * c.confidence)));
  plot.stem = "envelope";
  plot.title = fmt::format("Horizontal RMS position error: {} samples at fidelity {} (shaded: {}% interval), "
                           "dotted: covariance",
                           c.samples, to_string(c.fidelity), format_number(100 * c.confidence));
  plot.band_name = fmt::format("{}% interval", format_number(100 * c.confidence));
  plot.x_label = "time on the scheme's clock [min]";
  plot.y_label = fmt::format("RMS horizontal error [{}]", length_suffix(unit));
  for (const double t : c.report_times_s) plot.marked_x.push_back(t / 60.0);
  std::erase_if(plot.panels, [](const PlotPanel& p) { return p.lines.empty(); });
  f.envelope_plot = plot;
  return f;
}

CovarianceFiles render_covariance(const StudyConfig& c, const StudyLayout& l, const StudyMap& map, LengthUnit unit) {
  const double k = length_factor(unit);
  const std::string rms_col = fmt::format("rms_{}", length_suffix(unit));
  const std::string u = length_suffix(unit);
  Table cov({"scheme", "system", "axis", "t_min", rms_col, "cep50_" + u, "cep95_" + u, "drms2_" + u, "radial_rate_nmiph"});
  Table cov_grid({"scheme", "system", "axis", "t_min", rms_col});
  Table budget({"scheme", "system", "axis", "t_min", "parameter", "variance_share"});
  const std::vector<std::string> sources = map.budget_sources();
  const std::vector<std::vector<double>> shares = map.budget_shares();
  std::vector<HorizontalPoint> horizontal;
  CovarianceFiles f;
  f.covariance_json = Json::array();
  for (size_t o = 0; o < l.outputs.size(); ++o) {
    const OutputSpec& spec = l.outputs[o];
    const double t = l.times_s[spec.time_index];
    const std::vector<std::string> key = {std::string(to_string(spec.scheme)),
                                          std::to_string(system_number(spec.system)),
                                          std::string(to_string(spec.axis)), fmt_minutes(t)};
    std::vector<std::string> row = key;
    row.push_back(format_number(k * map.predicted_rms()[o]));
    if (l.is_grid_time[spec.time_index]) cov_grid.add_row(row);
    if (!l.is_report_time[spec.time_index]) continue;
    Json j = Json::object();
    j["scheme"] = key[0];
    j["system"] = system_number(spec.system);
    j["axis"] = key[2];
    j["t_min"] = t / 60.0;
    j["rms_m"] = map.predicted_rms()[o];
    if (spec.axis == Axis::kHorizontal) {
      const CovarianceAccuracy a = covariance_accuracy(map, o, t);
      for (const double v : {k * a.cep50_m, k * a.cep95_m, k * a.drms2_m}) row.push_back(format_number(v));
      row.push_back(a.rate_nmiph ? format_number(*a.rate_nmiph) : "");
      j["cep50_m"] = a.cep50_m;
      j["cep95_m"] = a.cep95_m;
      j["drms2_m"] = a.drms2_m;
      j["radial_rate_nmiph"] = a.rate_nmiph ? Json(*a.rate_nmiph) : Json();
      // Exact values: no interval (the RMS and 2DRMS exact, the CEP exact for the Gaussian).
      horizontal.push_back({key[0], std::string(clock_of(spec.scheme)), system_number(spec.system), t / 60.0,
                            k * map.predicted_rms()[o], std::nullopt,
                            map.ready_time_s(scheme_index(c, spec.scheme)) / 60.0,
                            AccuracyFigures{k * a.cep50_m, 0, k * a.drms2_m, 0, a.rate_nmiph.value_or(0), 0}});
    } else {
      row.insert(row.end(), 4, "");
    }
    cov.add_row(row);
    f.covariance_json.push_back(j);
    for (std::size_t p = 0; p < sources.size(); ++p) {
      if (shares[o][p] <= 0) continue;
      std::vector<std::string> b = key;
      b.push_back(sources[p]);
      b.push_back(format_number(shares[o][p]));
      budget.add_row(b);
    }
  }
  f.covariance_csv = render_csv(cov);
  f.covariance_grid_csv = render_csv(cov_grid);
  f.budget_csv = render_csv(budget);
  f.budget_plot = budget_figure(c, l, map);
  f.covariance_md = fmt::format("# insmc covariance: exact linear RMS\n\nfidelity {}, latitude {} deg.\n\n{}",
                                to_string(c.fidelity), format_number(c.model.latitude_rad / kDegToRad),
                                render_markdown(cov));
  f.summary_text = render_horizontal_summary(
      horizontal, fmt::format("Horizontal RMS position error [{}], exact (linear model); 2DRMS = 2·RMS; CEP50, "
                              "CEP/t of a Gaussian of the exact mean and covariance; ready: minutes to flight.",
                              length_suffix(unit)));
  return f;
}

Json output_row_json(const OutputSpec& spec, double t_s, const OutputSummary& s, double ready_time_s) {
  Json j = Json::object();
  j["scheme"] = std::string(to_string(spec.scheme));
  j["system"] = system_number(spec.system);
  j["clock"] = std::string(clock_of(spec.scheme));
  j["axis"] = std::string(to_string(spec.axis));
  j["t_min"] = t_s / 60.0;
  j["n"] = static_cast<double>(s.n);
  j["rms_m"] = s.rms;
  j["rms_lo_m"] = s.rms_lo;
  j["rms_hi_m"] = s.rms_hi;
  j["mean_m"] = s.mean;
  j["std_m"] = s.std;
  j["min_m"] = s.min;
  j["max_m"] = s.max;
  j["p95_m"] = s.p95_abs;
  j["ready_time_min"] = ready_time_s / 60.0;
  return j;
}

Json settings_json(const StudyConfig& c, SettingsOf of) {
  Json s = Json::object();
  s["program"] = "insmc";
  s["version"] = kVersion;
  const bool monte_carlo = of == SettingsOf::kMonteCarlo;
  if (monte_carlo) {
    s["seed"] = static_cast<double>(c.seed);
    s["samples"] = static_cast<double>(c.samples);
    s["threads"] = c.threads;
  }
  s["fidelity"] = std::string(to_string(c.fidelity));
  Json systems = Json::array(), schemes = Json::array();
  for (System sy : c.systems) systems.push_back(system_number(sy));
  for (Scheme sc : c.schemes) schemes.push_back(std::string(to_string(sc)));
  s["systems"] = systems;
  s["schemes"] = schemes;
  s["latitude_rad"] = c.model.latitude_rad;
  s["leveling_gain_ratio"] = c.model.leveling_gain_ratio;
  if (monte_carlo) s["confidence"] = c.confidence;
  s["grid_step_s"] = c.grid_step_s;
  s["grid_end_s"] = c.grid_end_s;
  Json report = Json::array();
  for (double t : c.report_times_s) report.push_back(t);
  s["report_times_s"] = report;
  Json params = Json::object();
  for (const auto& spec : catalogue()) {
    const ParameterDistribution& p = c.uncertainties.at(spec.index);
    Json j = Json::object();
    j["distribution"] = p.describe();
    j["bound_si"] = p.bound_si;
    if (p.kind == DistributionKind::kFixed) j["fixed_si"] = p.fixed_si;
    params[std::string(spec.name)] = j;
  }
  s["uncertainties"] = params;
  return s;
}

}  // namespace insmc::mc
