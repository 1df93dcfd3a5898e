#include "montecarlo/study/run/sweep_study.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fmt/format.h>
#include <string_view>
#include <utility>

#include "lib/common/input_error.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/write/accuracy_cells.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/interval_format.h"
#include "montecarlo/report/markdown.h"
#include "montecarlo/study/write/study_writer.h"

namespace insmc::mc {
namespace {

/// Every point is a full study: 100 values per quantity and 1000 points in
/// all (minutes each at the default samples) bound a sweep's run time.
constexpr std::size_t kMaxSweepValues = 100, kMaxSweepPoints = 1000;
/// Every point's rows (one per output at a report time) are kept until the
/// last point, in sweep.csv's table and sweep.json's tree: about 8 KB a row
/// together (990 points of 168 rows peaked at 1.36 GB, 1.55 GB with --out),
/// so 80,000 rows keep a sweep under 1 GB.
constexpr std::size_t kMaxSweepRows = 80'000;

/// The study of point `p` (row-major over the axes); `idx` gets each axis's value index.
mc::StudyConfig point_config(const mc::StudyConfig& base, const std::vector<SweepAxis>& axes, std::size_t p,
                             std::vector<std::size_t>& idx) {
  mc::StudyConfig c = base;
  c.with_grid = false;
  if (c.test.fit_u4 == FitU4::kYes) c.test.fit_u4 = FitU4::kAuto;  // each point fits what it can resolve
  idx.assign(axes.size(), 0);
  std::size_t rest = p;
  for (std::size_t i = axes.size(); i-- > 0;) {
    idx[i] = rest % axes[i].texts.size();
    rest /= axes[i].texts.size();
    axes[i].apply(c, idx[i]);
  }
  mc::validate(c);
  return c;
}

/// The first swept quantity as the user gave it: when every value carries
/// the same unit (5min,10min,15min; 1meru,10meru), the numbers in that unit;
/// otherwise SI. Logarithmic when it spans a factor of 20 or more.
struct AxisInUserUnits {
  std::vector<double> x;
  std::string label;
  std::string unit;  ///< the unit typed, empty when SI
  bool logarithmic = false;
};

AxisInUserUnits in_user_units(const SweepAxis& a) {
  AxisInUserUnits out{a.values_si, a.column, "", false};
  std::string common;
  std::vector<double> given;
  for (std::size_t i = 0; i < a.texts.size(); ++i) {
    const std::string& text = a.texts[i];
    const std::size_t eq = text.rfind('=');
    const std::string value = eq == std::string::npos ? text : text.substr(eq + 1);
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    const std::string unit = end ? std::string(end) : std::string();
    if (end == value.c_str() || unit.empty() || (i > 0 && unit != common)) {
      given.clear();
      break;
    }
    common = unit;
    given.push_back(v);
  }
  if (!given.empty()) {
    out.x = given;
    out.unit = common;
    out.label = fmt::format("{} [{}]", quantity_name(a.column), common);
  }
  const auto [lo, hi] = std::minmax_element(out.x.begin(), out.x.end());
  out.logarithmic = lo != out.x.end() && *lo > 0 && *hi / *lo >= 20;
  return out;
}

/// The CSV column of a swept quantity in the unit typed (beside its SI
/// column): gyro_drift.bound in meru → gyro_drift.bound_meru, in deg/h →
/// gyro_drift.bound_deg_per_h.
std::string user_unit_column(const SweepAxis& a, const std::string& unit) {
  // Letters and digits kept; /, °, µ (micro sign or Greek mu) spelled out.
  static const std::pair<std::string_view, std::string_view> kSpelled[] = {
      {"/", "_per_"}, {"\u00b0", "deg"}, {"\u00b5", "u"}, {"\u03bc", "u"}, {"\u221a", "sqrt"}};
  std::string suffix;
  for (std::size_t i = 0; i < unit.size();) {
    bool spelled = false;
    for (const auto& [text, word] : kSpelled)
      if (unit.compare(i, text.size(), text) == 0) {
        suffix += word;
        i += text.size();
        spelled = true;
        break;
      }
    if (spelled) continue;
    const unsigned char ch = static_cast<unsigned char>(unit[i++]);
    if (std::isalnum(ch)) suffix += static_cast<char>(ch);
    else if (!suffix.empty() && suffix.back() != '_') suffix += '_';
  }
  std::string clean;  // no doubled or trailing underscores
  for (const char ch : suffix)
    if (ch != '_' || (!clean.empty() && clean.back() != '_')) clean += ch;
  while (!clean.empty() && clean.back() == '_') clean.pop_back();
  return quantity_name(a.column) + "_" + (clean.empty() ? "user" : clean);
}

/// The unit-typed column of an axis, or empty when there is none (SI given,
/// or a name that would repeat the SI column's, e.g. 300s,600s).
std::string typed_column(const SweepAxis& a, const std::string& unit) {
  if (unit.empty()) return "";
  const std::string name = user_unit_column(a, unit);
  return name == a.column ? "" : name;
}

/// One line of the terminal's summary: a point's scheme and system with the
/// horizontal RMS at each report time.
struct SummaryRow {
  std::string scheme, system;
  std::vector<std::string> rms;  ///< per report time
  std::string accuracy, fitted;
};
/// A point's horizontal RMS at the last report time in the figure: one
/// panel per scheme; one line per system and combination of the other swept
/// quantities (every line of a product sweep).
void add_to_plot(mc::PanelFigure& plot, const mc::OutputSpec& spec, int scheme_i, const std::vector<SweepAxis>& axes,
                 const std::vector<std::size_t>& idx, const AxisInUserUnits& x_axis, const mc::OutputSummary& s,
                 double k) {
  if (plot.panels.size() <= static_cast<std::size_t>(scheme_i)) plot.panels.resize(static_cast<std::size_t>(scheme_i) + 1);
  mc::PlotPanel& panel = plot.panels[static_cast<std::size_t>(scheme_i)];
  panel.title = std::string(to_string(spec.scheme));
  std::string name = fmt::format("system {}", system_number(spec.system));
  std::size_t others = 0;
  for (std::size_t i = 1; i < axes.size(); ++i) {
    name += fmt::format(", {} {}", quantity_name(axes[i].column), axes[i].texts[idx[i]]);
    others = others * axes[i].texts.size() + idx[i];
  }
  mc::PlotLine* line = nullptr;
  for (mc::PlotLine& l : panel.lines)
    if (l.name == name) line = &l;
  if (!line) {
    // A colour per system and combination of the other quantities;
    // system 2 dashed as well (told apart in grey print).
    const int system_i = spec.system == System::kGyrocompass ? 1 : 0;
    panel.lines.push_back({name, {}, {}, {}, {}, {}, static_cast<int>(2 * others) + system_i, system_i == 1});
    line = &panel.lines.back();
  }
  line->x.push_back(x_axis.x[idx[0]]);
  line->y.push_back(k * s.rms);
  line->lo.push_back(k * s.rms_lo);
  line->hi.push_back(k * s.rms_hi);
  line->marks.push_back({x_axis.x[idx[0]], k * s.rms, k * s.rms_lo, k * s.rms_hi});  // the studied points
}

/// Where the terms the estimators fit change between neighbouring points
/// of the first swept quantity (the others held): from and to are the
/// point names before and after, at_index the first quantity's index after.
struct EstimatorSwitch {
  System system;
  std::string before, after, from, to;
  std::size_t at_index;
};

std::string point_label(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& idx) {
  std::string name;
  for (std::size_t i = 0; i < axes.size(); ++i)
    name += fmt::format("{}{}={}", i ? " " : "", quantity_name(axes[i].column), axes[i].texts[idx[i]]);
  return name;
}

std::vector<EstimatorSwitch> estimator_switches(const mc::StudyConfig& base, const std::vector<SweepAxis>& axes,
                                                const std::vector<std::vector<std::size_t>>& idx,
                                                const std::vector<std::vector<std::string>>& fitted) {
  std::vector<EstimatorSwitch> out;
  for (std::size_t p = 0; p < idx.size(); ++p) {
    if (idx[p][0] == 0) continue;
    std::vector<std::size_t> prev = idx[p];
    --prev[0];
    for (std::size_t q = 0; q < idx.size(); ++q) {
      if (idx[q] != prev) continue;
      for (std::size_t j = 0; j < base.systems.size() && j < fitted[p].size() && j < fitted[q].size(); ++j)
        if (fitted[p][j] != fitted[q][j])
          out.push_back({base.systems[j], fitted[q][j], fitted[p][j], point_label(axes, idx[q]),
                         point_label(axes, idx[p]), idx[p][0]});
    }
  }
  return out;
}

/// sweep.json's `estimator_switches`; each switch marked on the figure's x axis.
mc::Json switches_json(const std::vector<EstimatorSwitch>& switches, const AxisInUserUnits& x_axis,
                       mc::PanelFigure& plot) {
  mc::Json list = mc::Json::array();
  for (const EstimatorSwitch& w : switches) {
    mc::Json j = mc::Json::object();
    j["system"] = system_number(w.system);
    j["before"] = w.before;
    j["after"] = w.after;
    j["from"] = w.from;
    j["to"] = w.to;
    list.push_back(j);
    if (std::find(plot.marked_x.begin(), plot.marked_x.end(), x_axis.x[w.at_index]) == plot.marked_x.end())
      plot.marked_x.push_back(x_axis.x[w.at_index]);
  }
  return list;
}

std::string switches_markdown(const mc::StudyConfig& base, const std::vector<EstimatorSwitch>& switches) {
  if (switches.empty()) return "";
  std::string md = fmt::format(
      "\nThe estimators change along the sweep{}: a step in the RMS at these points is the estimator's, not the swept "
      "quantity's (the figure marks them; `--fit-u4 no` or `yes` holds the estimator fixed):\n\n",
      base.test.fit_u4 == FitU4::kAuto ? " (--fit-u4 auto, the default: U4 is fitted once the test run resolves it)"
                                        : "");
  for (const EstimatorSwitch& w : switches)
    md += fmt::format("- system {}: fits {} at {}, {} at {}\n", system_number(w.system), w.before, w.from, w.after, w.to);
  return md;
}

}  // namespace

void check_sweep_size(const std::vector<SweepAxis>& axes) {
  std::size_t points = 1;
  for (const auto& a : axes) {
    if (a.texts.size() > kMaxSweepValues)
      throw InputError(fmt::format("sweep {}", a.column), fmt::format("{} values", a.texts.size()),
                       fmt::format("at most {} values per swept quantity", kMaxSweepValues));
    points *= a.texts.size();
    if (points > kMaxSweepPoints)
      throw InputError("sweep", fmt::format("more than {} points", kMaxSweepPoints),
                       fmt::format("at most {} points in the product of the swept quantities", kMaxSweepPoints));
  }
}

std::string quantity_name(std::string_view column) {
  for (const std::string_view si : {"_s", "_m", "_mps", "_mps2", "_rad", "_radps", "_si"})
    if (column.size() > si.size() && column.ends_with(si)) {
      column.remove_suffix(si.size());
      break;
    }
  return std::string(column);
}


void check_sweep_points(const mc::StudyConfig& base, const std::vector<SweepAxis>& axes) {
  std::size_t points = 1;
  for (const auto& a : axes) points *= a.texts.size();
  std::vector<std::size_t> idx;
  for (std::size_t p = 0; p < points; ++p) point_config(base, axes, p, idx);
  if (axes.empty()) return;
  // The rows the sweep keeps: every point has the same outputs (no swept
  // quantity changes the schemes, systems or report times).
  const mc::StudyConfig first = point_config(base, axes, 0, idx);
  const std::size_t per_point = first.schemes.size() * first.systems.size() * first.report_times_s.size() * 4;
  if (points * per_point > kMaxSweepRows)
    throw InputError("sweep", fmt::format("{} points", points),
                     fmt::format("{} points of {} rows ({} schemes × {} systems × {} report times × 4 axes) make {} "
                                 "rows of sweep.csv and sweep.json, all held until the last point; at most {} rows "
                                 "(1 GB): at most {} points at these settings",
                                 points, per_point, first.schemes.size(), first.systems.size(),
                                 first.report_times_s.size(), points * per_point, kMaxSweepRows,
                                 kMaxSweepRows / per_point));
}

SweepFiles run_sweep(const mc::StudyConfig& base, const std::vector<SweepAxis>& axes, mc::LengthUnit unit,
                     const StudyRunner& run) {
  const double k = mc::length_factor(unit);
  const std::string u = mc::length_suffix(unit);
  std::vector<AxisInUserUnits> typed;
  for (const SweepAxis& a : axes) typed.push_back(in_user_units(a));
  std::vector<std::string> header;
  std::vector<std::string> typed_columns;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    header.push_back(axes[i].column);
    typed_columns.push_back(typed_column(axes[i], typed[i].unit));
    if (!typed_columns.back().empty()) header.push_back(typed_columns.back());
  }
  for (const char* c : {"scheme", "system", "clock", "axis", "t_min", "n"}) header.emplace_back(c);
  for (const char* q : {"rms", "rms_lo", "rms_hi", "mean", "std", "min", "max", "p95"})
    header.push_back(fmt::format("{}_{}", q, u));
  header.emplace_back("ready_time_min");
  header.emplace_back("fitted_terms");
  for (std::string& column : mc::accuracy_header(unit)) header.push_back(std::move(column));
  mc::Table table(header);
  std::vector<std::string> summary_header{"point", "scheme", "system"};
  for (const double t : base.report_times_s)
    summary_header.push_back(fmt::format("RMS [{}] {} min", u, mc::format_number(t / 60)));
  summary_header.push_back(mc::readable_accuracy_header(unit).front());
  summary_header.emplace_back("fitted");
  mc::Table summary(summary_header);
  mc::PanelFigure plot;
  check_sweep_size(axes);
  const AxisInUserUnits& x_axis = typed[0];
  std::size_t points = 1;
  for (const auto& a : axes) points *= a.texts.size();
  mc::Json point_list = mc::Json::array();
  std::vector<std::size_t> idx;
  // Each point's indices and the terms its estimators fit, per system: a
  // default that changes the estimator along the sweep (--fit-u4 auto fits
  // U4 once the test run resolves it) is said where it switches.
  std::vector<std::vector<std::size_t>> point_idx;
  std::vector<std::vector<std::string>> point_fitted;
  // Every point is checked before the first is run: a value out of range
  // late in the list must not cost the points before it.
  for (std::size_t p = 0; p < points; ++p) point_config(base, axes, p, idx);
  for (std::size_t p = 0; p < points; ++p) {
    const mc::StudyConfig c = point_config(base, axes, p, idx);
    const mc::StudyLayout layout = mc::make_layout(c);
    const mc::StudyMap map(c, layout);
    const mc::StudyAccumulator acc = run ? run(c, map) : mc::run_blocks(c, map, 0, mc::block_count(c.samples));
    point_idx.push_back(idx);
    point_fitted.emplace_back();
    for (std::size_t j = 0; j < c.systems.size(); ++j) point_fitted.back().push_back(map.fitted_terms(static_cast<int>(j)));
    std::string point_name;
    mc::Json point = mc::Json::object(), values = mc::Json::object(), rows = mc::Json::array();
    for (std::size_t i = 0; i < axes.size(); ++i) {
      point_name += fmt::format("{}{}={}", i ? " " : "", quantity_name(axes[i].column), axes[i].texts[idx[i]]);
      values[axes[i].column] = axes[i].values_si[idx[i]];
    }
    std::vector<SummaryRow> point_rows;
    for (std::size_t o = 0; o < layout.outputs.size(); ++o) {
      const auto& spec = layout.outputs[o];
      if (!layout.is_report_time[spec.time_index]) continue;
      const mc::OutputSummary s = acc.outputs()[o].summarize(c.confidence);
      const std::optional<mc::HorizontalAccuracy> accuracy = acc.accuracy(layout, o, s, c.confidence);
      int scheme_i = 0;
      while (c.schemes[static_cast<std::size_t>(scheme_i)] != spec.scheme) ++scheme_i;
      std::vector<std::string> row;
      for (std::size_t i = 0; i < axes.size(); ++i) {
        row.push_back(mc::format_number(axes[i].values_si[idx[i]]));
        if (!typed_columns[i].empty()) row.push_back(mc::format_number(typed[i].x[idx[i]]));
      }
      const std::size_t swept_columns = row.size();
      const double t = layout.times_s[spec.time_index];
      const std::string& fitted = map.fitted_terms(map.system_index(o));
      for (const std::string& cell :
           {std::string(to_string(spec.scheme)), std::to_string(system_number(spec.system)),
            std::string(clock_of(spec.scheme)), std::string(to_string(spec.axis)), mc::format_number(t / 60),
            std::to_string(s.n), mc::format_number(k * s.rms), mc::format_number(k * s.rms_lo),
            mc::format_number(k * s.rms_hi), mc::format_number(k * s.mean), mc::format_number(k * s.std),
            mc::format_number(k * s.min), mc::format_number(k * s.max), mc::format_number(k * s.p95_abs),
            mc::format_number(map.ready_time_s(scheme_i) / 60), fitted})
        row.push_back(cell);
      for (std::string& cell : mc::accuracy_cells(accuracy, unit)) row.push_back(std::move(cell));
      table.add_row(row);
      mc::Json r = mc::output_row_json(spec, t, s, map.ready_time_s(scheme_i));
      r["fitted_terms"] = fitted;
      mc::add_accuracy_json(r, accuracy);
      rows.push_back(r);
      if (spec.axis == mc::Axis::kHorizontal) {
        SummaryRow* line = nullptr;
        for (SummaryRow& r : point_rows)
          if (r.scheme == row[swept_columns] && r.system == row[swept_columns + 1]) line = &r;
        if (!line) {
          point_rows.push_back({row[swept_columns], row[swept_columns + 1],
                                std::vector<std::string>(c.report_times_s.size(), "—"), "—", fitted});
          line = &point_rows.back();
        }
        for (std::size_t q = 0; q < c.report_times_s.size() && q < line->rms.size(); ++q)
          if (std::abs(t - c.report_times_s[q]) < 1e-6)
            line->rms[q] = mc::format_with_interval(k * s.rms, k * (s.rms_hi - s.rms_lo) / 2);
      }
      if (spec.axis == mc::Axis::kHorizontal && std::abs(t - c.report_times_s.back()) < 1e-6) {
        for (SummaryRow& r : point_rows)
          if (r.scheme == row[swept_columns] && r.system == row[swept_columns + 1])
            r.accuracy = mc::readable_accuracy_cells(accuracy, unit).front();
        add_to_plot(plot, spec, scheme_i, axes, idx, x_axis, s, k);
      }
    }
    for (const SummaryRow& r : point_rows) {
      std::vector<std::string> cells{point_name, r.scheme, r.system};
      cells.insert(cells.end(), r.rms.begin(), r.rms.end());
      cells.push_back(r.accuracy);
      cells.push_back(r.fitted);
      summary.add_row(cells);
    }
    point["values_si"] = values;
    point["rows"] = rows;
    point_list.push_back(point);
  }
  SweepFiles f;
  mc::Json swept = mc::Json::array();
  for (const SweepAxis& a : axes) {
    mc::Json axis = mc::Json::object(), texts = mc::Json::array(), values = mc::Json::array();
    for (std::size_t i = 0; i < a.texts.size(); ++i) {
      texts.push_back(a.texts[i]);
      values.push_back(a.values_si[i]);
    }
    axis["column"] = a.column;
    axis["texts"] = texts;
    axis["values_si"] = values;
    swept.push_back(axis);
  }
  f.json["axes"] = swept;
  f.json["points"] = point_list;
  const std::vector<EstimatorSwitch> switches = estimator_switches(base, axes, point_idx, point_fitted);
  f.json["estimator_switches"] = switches_json(switches, x_axis, plot);
  f.sweep_csv = mc::render_csv(table);
  f.summary_md = mc::render_markdown(summary) + switches_markdown(base, switches);
  plot.stem = "sweep";
  plot.title = fmt::format("Horizontal RMS at {} min against {} (shaded: {}% confidence interval){}",
                           mc::format_number(base.report_times_s.back() / 60), x_axis.label,
                           mc::format_number(100 * base.confidence),
                           switches.empty() ? ""
                                            : "; dotted verticals: where the estimators start fitting other terms "
                                              "(sweep.md), a step in the RMS there is the estimator's");
  plot.band_name = fmt::format("{}% interval", mc::format_number(100 * base.confidence));
  plot.x_label = x_axis.label;
  plot.y_label = fmt::format("RMS horizontal error [{}]", u);
  plot.log_x = x_axis.logarithmic;
  std::erase_if(plot.panels, [](const mc::PlotPanel& p) { return p.lines.empty(); });
  f.plot = plot;
  return f;
}

}  // namespace insmc::mc
