#include "montecarlo/records/noise/noise_figures.h"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "lib/noise/noise_budget.h"
#include "lib/noise/noise_terms.h"
#include "lib/units/units.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::noise {
namespace {


/// Per sensor kind: the unit the report's tables use for rates, and its size in SI.
struct DisplayRate {
  const char* unit;
  double si;
};
DisplayRate display_rate(SensorKind kind) {
  return kind == SensorKind::kGyro ? DisplayRate{"deg/h", kDegphToRadps} : DisplayRate{"µg", kUgToMps2};
}

/// A reference level drawn across the panel's cluster times as a line of
/// two points (a level, or a −1/2 slope through its end points).
mc::PlotLine reference(std::string name, double tau0, double tau1, double y0, double y1, int colour, bool thin) {
  mc::PlotLine line;
  line.name = std::move(name);
  line.x = {tau0, tau1};
  line.y = {y0, y1};
  line.colour = colour;
  line.thin = thin;
  line.dashed = !thin;
  return line;
}

}  // namespace

mc::PanelFigure noise_allan_figure(const NoiseAnalysis& a, const std::array<SheetLevels, 2>& sheet) {
  mc::PanelFigure f;
  f.stem = "allan";
  f.title = "Overlapping Allan deviation: data (shaded and bars: its interval) and fitted model (dashed)";
  f.x_label = "cluster time τ [s]";
  f.log_x = f.log_y = true;
  f.columns = 1;
  for (int panel_index = 0; panel_index < 2; ++panel_index) {
    const SensorKind kind = panel_index == 0 ? SensorKind::kGyro : SensorKind::kAccelerometer;
    const DisplayRate rate = display_rate(kind);
    mc::PlotPanel panel;
    panel.title = kind == SensorKind::kGyro ? "gyros" : "accelerometers";
    panel.y_label = fmt::format("Allan deviation [{}]", rate.unit);
    double tau0 = 0, tau1 = 0;
    for (int i = 0; i < 3; ++i) {
      const ChannelNoise& ch = a.channels[static_cast<std::size_t>(3 * panel_index + i)];
      mc::PlotLine data, model;
      data.name = ch.name;
      model.name = ch.name + " fit";
      data.colour = model.colour = i;
      model.dashed = true;
      for (const AllanRow& r : ch.allan) {
        if (!(r.tau_s > 0 && r.adev > 0)) continue;
        tau0 = tau0 > 0 ? std::min(tau0, r.tau_s) : r.tau_s;
        tau1 = std::max(tau1, r.tau_s);
        const double y = r.adev / rate.si;
        const double lo = r.lower > 0 ? r.lower / rate.si : y, hi = r.upper > 0 ? r.upper / rate.si : y;
        data.x.push_back(r.tau_s);
        data.y.push_back(y);
        data.lo.push_back(lo);
        data.hi.push_back(hi);
        data.marks.push_back({r.tau_s, y, lo, hi});
        if (r.model_adev > 0) {
          model.x.push_back(r.tau_s);
          model.y.push_back(r.model_adev / rate.si);
        }
      }
      if (data.x.empty()) continue;
      panel.lines.push_back(std::move(data));
      if (!model.x.empty()) panel.lines.push_back(std::move(model));
    }
    if (tau1 > tau0) {
      // Table 3.1's bound on the sensor's bias as a level: a curve above it
      // near the Schuler period means the bias wanders more than Table 3.1
      // lets a bias be (docs/noise.md §4).
      const double bound = table31_bound_si(kind) / rate.si;
      panel.lines.push_back(reference(fmt::format("Table 3.1 bias bound ({})", table31_bound_text(kind)),
                                      tau0, tau1, bound, bound, 6, true));
      const SheetLevels& s = sheet[static_cast<std::size_t>(panel_index)];
      // The data sheet: its white noise as σ = N/√τ, its bias instability
      // as the floor 0.664 B (IEEE Std 952, C.12 and C.15).
      if (s.white && *s.white > 0) {
        const auto level = [&](double tau) {
          return *s.white * std::sqrt(avar_shape(NoiseTerm::kWhiteRate, tau, 1)) / rate.si;
        };
        panel.lines.push_back(reference(kind == SensorKind::kGyro ? "data sheet ARW (N/√τ)" : "data sheet VRW (N/√τ)",
                                        tau0, tau1, level(tau0), level(tau1), 6, false));
      }
      if (s.instability && *s.instability > 0) {
        const double floor =
            *s.instability * std::sqrt(avar_shape(NoiseTerm::kBiasInstability, 1, 1)) / rate.si;
        panel.lines.push_back(
            reference("data sheet bias instability (0.664 B)", tau0, tau1, floor, floor, 3, false));
      }
    }
    f.panels.push_back(std::move(panel));
  }
  return f;
}

mc::PanelFigure stationarity_figure(const SensorRecording& rec, const NoiseAnalysis& a) {
  const double alpha = a.alpha;
  mc::PanelFigure f;
  f.stem = "stationarity";
  f.title = "Block means of each recording minus its mean after the first part (shaded: the first part; the level "
            "across it: the first part's mean, the test's statistic; dark band: where it stays if the first part is "
            "like the rest)";
  f.x_label = "time in the recording [h]";
  f.signed_y = true;
  f.columns = 2;
  const double z = boost::math::quantile(boost::math::normal(), 1 - alpha / 2);
  for (std::size_t c = 0; c < kChannels; ++c) {
    const ChannelNoise& ch = a.channels[c];
    const DisplayRate rate = display_rate(ch.kind);
    const double part_s = ch.stationarity.first_part_s;
    const auto block = static_cast<std::size_t>(std::llround(part_s / 6 / rec.dt_s));
    const auto part = static_cast<std::size_t>(std::llround(part_s / rec.dt_s));
    mc::PlotPanel panel;
    panel.title = ch.name + (ch.stationarity.tested ? (ch.stationarity.stationary ? ": stationary" : ": NOT stationary")
                                                    : ": not tested (too short)");
    panel.y_label = fmt::format("block mean − rest mean [{}]", rate.unit);
    panel.shade_x0 = 0;
    panel.shade_x1 = part_s / 3600;
    if (ch.stationarity.tested) {
      // The band of a stationary first part's mean: ± z_{1−α/2} of (N.6).
      mc::PlotLine band;
      band.name = fmt::format("first part like the rest: ±{:.2g} sd ({:g} % level)", z, 100 * alpha);
      band.x = {0, part_s / 3600};
      band.y = {0, 0};
      const double half = z * ch.stationarity.expected_sd / rate.si;
      band.lo = {-half, -half};
      band.hi = {half, half};
      band.colour = 6;
      band.thin = true;
      panel.lines.push_back(std::move(band));
    }
    for (std::size_t r = 0; r < rec.runs.size() && block > 0; ++r) {
      const Segment& run = rec.runs[r];
      const std::vector<double>& y = rec.channel[c];
      const std::size_t rest_n = run.size() > part ? run.size() - part : 0;
      if (rest_n == 0) continue;
      double rest = 0, first = 0;
      for (std::size_t k = run.begin + part; k < run.end; ++k) rest += y[k];
      rest /= static_cast<double>(rest_n);
      for (std::size_t k = run.begin; k < run.begin + part; ++k) first += y[k];
      first /= static_cast<double>(part);
      mc::PlotLine line;
      line.name = r < rec.run_names.size() ? std::filesystem::path(rec.run_names[r]).filename().string()
                                           : fmt::format("recording {}", r + 1);
      line.colour = static_cast<int>(r);
      for (std::size_t b = run.begin; b + block <= run.end; b += block) {
        double m = 0;
        for (std::size_t k = b; k < b + block; ++k) m += y[k];
        const double t_h = (static_cast<double>(b - run.begin) + static_cast<double>(block) / 2.0) * rec.dt_s / 3600;
        line.x.push_back(t_h);
        line.y.push_back((m / static_cast<double>(block) - rest) / rate.si);
        line.marks.push_back({line.x.back(), line.y.back(), line.y.back(), line.y.back()});
      }
      if (line.x.empty()) continue;
      const int colour = line.colour;
      const std::string name = line.name;
      panel.lines.push_back(std::move(line));
      if (ch.stationarity.tested && run.size() >= 2 * part) {
        mc::PlotLine mean;
        mean.name = name + ": first part's mean";
        mean.x = {0, part_s / 3600};
        mean.y = {(first - rest) / rate.si, (first - rest) / rate.si};
        mean.colour = colour;
        panel.lines.push_back(std::move(mean));
      }
    }
    f.panels.push_back(std::move(panel));
  }
  return f;
}

}  // namespace insmc::noise
