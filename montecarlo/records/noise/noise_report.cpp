#include "montecarlo/records/noise/noise_report.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "lib/calibration/multiposition.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/noise/noise_budget.h"
#include "lib/noise/recording.h"
#include "lib/noise/table31_reading.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"
#include "lib/units/units.h"
#include "montecarlo/records/noise/noise_figures.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::noise {
namespace {




std::string g3(double v) { return fmt::format("{:.3g}", v); }

/// A Gauss–Markov term with T_c within twice the first cluster time is the
/// sensor's bandwidth (its samples are filtered), white noise beyond:
/// N_eff = √(N² + 2σ²T_c). nullopt otherwise.
std::optional<double> white_noise_effective(const ChannelNoise& ch) {
  const NoiseModel& m = ch.fit.model;
  if (ch.allan.empty() || !(m[NoiseTerm::kGaussMarkov] > 0) || m.correlation_time_s > 2 * ch.allan.front().tau_s)
    return std::nullopt;
  return std::sqrt(m[NoiseTerm::kWhiteRate] + 2 * m[NoiseTerm::kGaussMarkov] * m.correlation_time_s);
}


struct Orientation {
  std::size_t run;
  Vec3 mean_g;  ///< mean specific force over the kept samples [g]
};

std::vector<Orientation> orientations(const SensorRecording& rec, const NoiseAnalysis& a) {
  std::vector<Orientation> out;
  for (std::size_t r = 0; r < rec.runs.size(); ++r) {
    Vec3 sum = Vec3::Zero();
    double n = 0;
    for (const Segment& s : a.mask.kept)
      if (s.begin >= rec.runs[r].begin && s.end <= rec.runs[r].end)
        for (std::size_t k = s.begin; k < s.end; ++k, n += 1)
          for (int i = 0; i < 3; ++i) sum[i] += rec.channel[3 + i][k];
    if (n > 0) out.push_back({r, sum / n / kGravityMps2});
  }
  return out;
}

/// Distinct orientations: mean specific-force directions more than 5° apart.
/// Orientations more than the calibration's 5° apart.
std::size_t distinct_orientations(const std::vector<Orientation>& o) {
  std::vector<Vec3> mean_g;
  for (const Orientation& x : o) mean_g.push_back(x.mean_g);
  return calibration::distinct_directions(mean_g, calibration::MultipositionOptions{}.same_orientation_rad);
}

std::string identifiability(const std::vector<Orientation>& o, const std::vector<RecordingCalibration>& calibrations) {
  // A recording turned through still attitudes speaks for itself: its
  // calibration, or why there is none.
  std::string turned;
  for (const RecordingCalibration& rc : calibrations)
    if (!rc.result.accel.fitted && rc.result.orientations > 1)
      turned += fmt::format("{}: {} still attitudes, not calibrated: {}.\n", rc.recording, rc.result.segments.size(),
                            rc.result.accel.why_not);
  if (any_calibrated(calibrations))
    return "Recordings turned through several still attitudes: bias, scale factor and misalignment of both triads and "
           "the gyros' g-sensitivity are fitted below (a multi-position calibration). The noise terms above come "
           "from the still parts only when the turns are masked as disturbances (--mask on, the default).\n" +
           turned;
  if (!turned.empty()) return turned;
  const std::size_t n = distinct_orientations(o);
  if (n <= 1)
    return "One static orientation: scale factor, misalignment and g-sensitivity are not identifiable from these data "
           "(each acts as a constant bias in one orientation; separating them needs the sensor turned through "
           "several orientations, or rotated at known rates).\n";
  std::string s = fmt::format("{} distinct orientations (mean specific force more than 5° apart). ", n);
  std::string both;
  for (int i = 0; i < 3; ++i) {
    double lo = 1e9, hi = -1e9;
    for (const Orientation& x : o) lo = std::min(lo, x.mean_g[i]), hi = std::max(hi, x.mean_g[i]);
    if (hi - lo > 1.5) both += fmt::format("{}{}", both.empty() ? "" : ", ", "xyz"[i]);
  }
  s += both.empty() ? "No accelerometer axis sees both +g and −g, so scale factor and bias stay confounded on every axis. "
                    : fmt::format("Accelerometer axes that see both +g and −g, where bias and scale factor separate: {}. ", both);
  s += n >= 6 ? "With six or more orientations the accelerometer misalignments and the gyros' g-sensitivity become "
                "identifiable too, but across recordings the gyros cannot be calibrated (no turn between them): a "
                "multi-position calibration needs the turns in one recording.\n"
              : "Misalignment and g-sensitivity need more orientations (six for a full multi-position calibration).\n";
  return s;
}

/// A channel's white noise with its Gauss–Markov term at the sampling
/// interval, and an outer interval: each fitted term at its own interval's
/// end (N_eff grows with N, σ and T_c), so at least the stated confidence.
struct WhiteTogether {
  double value_si = 0, lower_si = 0, upper_si = 0;
};

std::optional<WhiteTogether> white_together(const ChannelNoise& ch, const TermFit& white) {
  const std::optional<double> n_eff = white_noise_effective(ch);
  if (!n_eff) return std::nullopt;
  const auto gm = std::find_if(ch.fit.terms.begin(), ch.fit.terms.end(),
                               [](const TermFit& t) { return t.term == NoiseTerm::kGaussMarkov; });
  if (gm == ch.fit.terms.end()) return std::nullopt;
  const auto combined = [](double n, double sigma, double tc) { return std::sqrt(n * n + 2 * sigma * sigma * tc); };
  return WhiteTogether{*n_eff, combined(white.lower_si, gm->lower_si, ch.fit.correlation_time_lower_s),
                       combined(white.upper_si, gm->upper_si, ch.fit.correlation_time_upper_s)};
}

/// The value of a fitted term in the units engineers quote: (value, unit).
std::pair<double, std::string> spec_value(NoiseTerm t, SensorKind kind, double v) {
  const double root_h = std::sqrt(kHourToS);  // 1/√s = 60/√h
  if (kind == SensorKind::kGyro) {
    switch (t) {
      case NoiseTerm::kQuantization: return {v / kArcsecToRad, "arcsec"};
      case NoiseTerm::kWhiteRate: return {v / kDegToRad * root_h, "deg/sqrt(h)"};
      case NoiseTerm::kBiasInstability:
      case NoiseTerm::kGaussMarkov: return {v / kDegphToRadps, "deg/h"};
      case NoiseTerm::kRateRandomWalk: return {v / kDegphToRadps * root_h, "deg/h/sqrt(h)"};
      case NoiseTerm::kRateRamp: return {v / kDegphToRadps * kHourToS, "deg/h/h"};
    }
  }
  switch (t) {
    case NoiseTerm::kQuantization: return {v, "m/s"};
    case NoiseTerm::kWhiteRate: return {v * root_h, "m/s/sqrt(h)"};
    case NoiseTerm::kBiasInstability:
    case NoiseTerm::kGaussMarkov: return {v / kUgToMps2, "ug"};
    case NoiseTerm::kRateRandomWalk: return {v / kUgToMps2 * root_h, "ug/sqrt(h)"};
    case NoiseTerm::kRateRamp: return {v / kUgToMps2 * kHourToS, "ug/h"};
  }
  return {v, ""};
}

/// The fitted white noise and bias instability beside the data sheet's:
/// the ratio, and whether the sheet's value lies inside the fitted interval.
std::string datasheet_section(const NoiseAnalysis& a, const Datasheet& sheet) {
  std::string md = "\n## Against the data sheet\n\nThe fitted term (with its interval) beside the value given with "
                   "--datasheet; \"not selected\" when the fit found the term indistinguishable from zero.\n\n"
                   "| channel | term | fitted | interval | data sheet | fitted / sheet | sheet inside interval |\n"
                   "|---|---|---:|---|---:|---:|---|\n";
  for (const ChannelNoise& ch : a.channels)
    for (const auto& [term, given] : {std::pair{NoiseTerm::kWhiteRate, sheet.white(ch.kind)},
                                      std::pair{NoiseTerm::kBiasInstability, sheet.instability(ch.kind)}}) {
      if (!given) continue;
      const auto [sheet_value, unit] = spec_value(term, ch.kind, *given);
      const double f = spec_value(term, ch.kind, 1.0).first;  // SI to the sheet's unit
      if (term == NoiseTerm::kBiasInstability && ch.readings.instability.found) {
        const double floor = ch.readings.instability.value_si;
        md += fmt::format("| {} | bias_instability (IEEE floor reading, min σ / 0.664 at τ = {:.3g} s) | {} {} | | {} "
                          "{} | {:.3g} | |\n",
                          ch.name, ch.readings.instability.tau_from_s, g3(floor * f), unit, g3(sheet_value), unit,
                          floor / *given);
      }
      if (!ch.fit.fits || ch.stuck) {
        md += fmt::format("| {} | {} | no model passes its fit test | | {} {} | | |\n", ch.name,
                          term_name(term, ch.kind), g3(sheet_value), unit);
        continue;
      }
      const auto fit = std::find_if(ch.fit.terms.begin(), ch.fit.terms.end(),
                                    [term = term](const TermFit& t) { return t.term == term; });
      if (fit == ch.fit.terms.end()) {
        md += fmt::format("| {} | {} | not selected | | {} {} | | |\n", ch.name, term_name(term, ch.kind),
                          g3(sheet_value), unit);
        continue;
      }
      // A Gauss–Markov term at the sampling interval is white noise too (the
      // note under the fitted terms): the sheet's white noise is compared
      // with both together, N_eff, as the note states it.
      const std::optional<WhiteTogether> together =
          term == NoiseTerm::kWhiteRate ? white_together(ch, *fit) : std::nullopt;
      const double value = together ? together->value_si : fit->value_si;
      const double lower = together ? together->lower_si : fit->lower_si;
      const double upper = together ? together->upper_si : fit->upper_si;
      const bool inside = *given >= lower && *given <= upper;
      md += fmt::format("| {} | {}{} | {} {} | [{}, {}] | {} {} | {} | {} |\n", ch.name, term_name(term, ch.kind),
                        together ? " (with the Gauss–Markov term at the sampling interval, √(N² + 2σ²T_c))" : "",
                        g3(value * f), unit, g3(lower * f), g3(upper * f), g3(sheet_value), unit,
                        *given > 0 ? fmt::format("{:.3g}", value / *given) : "-",
                        inside ? "yes" : lower > *given ? "**no: worse than the sheet**" : "no: better");
    }
  return md;
}

/// The fit test of each channel's model (docs/noise.md §3).
std::string fit_test_section(const NoiseAnalysis& a) {
  std::string md = fmt::format(
      "\n## Fit test of each model\n\nJ = rᵀS⁻¹r over the Allan levels the model is fitted to, S their covariance "
      "under the model itself (docs/noise.md §3), against χ²(levels − parameters) at α = {:g}: a model that fails is "
      "not reported as the fit. Where the shortest levels bend away from every standard term (a sensor's own "
      "filtering), they are left out one at a time until a model passes.\n\n"
      "| channel | levels | from τ [s] | J | degrees of freedom | p | verdict |\n|---|---:|---:|---:|---:|---:|---|\n",
      a.alpha);
  for (const ChannelNoise& ch : a.channels) {
    if (ch.stuck) {
      md += fmt::format("| {} | - | - | - | - | - | stuck: nothing to fit |\n", ch.name);
      continue;
    }
    const NoiseFit& f = ch.fit;
    const std::size_t from = std::min(f.first_level, ch.allan.size() - 1);
    md += fmt::format("| {} | {} of {} | {:.3g} | {:.3g} | {:g} | {:.2g} | {} |\n", ch.name, ch.allan.size() - from,
                      ch.allan.size(), ch.allan[from].tau_s, f.fit_statistic, f.fit_dof, f.fit_p_value,
                      f.fits ? (f.first_level > 0 ? fmt::format("passes (τ < {:.3g} s left out)", ch.allan[from].tau_s)
                                                  : std::string("passes"))
                             : std::string("**fails**: no model of the standard terms fits these levels; the IEEE "
                                           "readings stand in for it"));
  }
  return md;
}

/// A fitted term's value in the engineers' unit, "not selected" when the
/// passing model has none, "-" when no model passes.
std::string fitted_text(const ChannelNoise& ch, NoiseTerm term) {
  if (!ch.fit.fits || ch.stuck) return "-";
  for (const TermFit& t : ch.fit.terms)
    if (t.term == term) {
      const auto [v, unit] = spec_value(term, ch.kind, t.value_si);
      const double f = t.value_si > 0 ? v / t.value_si : 0;
      return fmt::format("{} [{}, {}]", g3(v), g3(t.lower_si * f), g3(t.upper_si * f));
    }
  return "not selected";
}

std::string reading_text(const SlopeReading& r, NoiseTerm term, SensorKind kind, const char* none) {
  if (!r.found) return none;
  const auto [v, unit] = spec_value(term, kind, r.value_si);
  return r.tau_from_s == r.tau_to_s ? fmt::format("{} {} (τ = {:.3g} s)", g3(v), unit, r.tau_from_s)
                                    : fmt::format("{} {} (τ {:.3g}–{:.3g} s)", g3(v), unit, r.tau_from_s, r.tau_to_s);
}

/// The IEEE Std 952 slope readings beside the fit (lib/noise/slope_readings.h).
std::string readings_section(const NoiseAnalysis& a, const Datasheet& sheet) {
  std::string md =
      "\n## IEEE Std 952 slope readings beside the fit\n\nRead off the Allan deviation (Annex C): the white noise "
      "from the −½ line at τ = 1 s, the bias instability from the floor (min σ / 0.664), the rate random walk from "
      "the +½ line at τ = 3 s where the curve ends on a +½ slope; the fitted value (its interval) beside each.\n\n"
      "| channel | white noise: reading | fit | bias instability: floor | fit | random walk: +½ reading | fit |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const ChannelNoise& ch : a.channels) {
    if (ch.stuck) {
      md += fmt::format("| {} | stuck | | | | | |\n", ch.name);
      continue;
    }
    const SlopeReadings& r = ch.readings;
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", ch.name,
                      reading_text(r.white, NoiseTerm::kWhiteRate, ch.kind, "no −½ slope"),
                      fitted_text(ch, NoiseTerm::kWhiteRate),
                      reading_text(r.instability, NoiseTerm::kBiasInstability, ch.kind, "-"),
                      fitted_text(ch, NoiseTerm::kBiasInstability),
                      reading_text(r.walk, NoiseTerm::kRateRandomWalk, ch.kind, "no +½ slope"),
                      fitted_text(ch, NoiseTerm::kRateRandomWalk));
  }
  for (const SensorKind kind : {SensorKind::kGyro, SensorKind::kAccelerometer})
    if (const std::optional<double> given = sheet.instability(kind)) {
      const auto [v, unit] = spec_value(NoiseTerm::kBiasInstability, kind, *given);
      md += fmt::format("\nThe data sheet's {} bias instability: {} {} (the floor readings above beside it).\n",
                        kind == SensorKind::kGyro ? "gyro" : "accelerometer", g3(v), unit);
    }
  return md;
}

std::string markdown(const SensorRecording& rec, const NoiseAnalysis& a, double confidence,
                     const Datasheet& sheet, const std::vector<RecordingCalibration>& calibrations) {
  std::string md = "# Sensor noise: overlapping Allan deviation and fitted terms\n\n";
  double total_s = 0;
  for (const Segment& r : rec.runs) total_s += static_cast<double>(r.size()) * rec.dt_s;
  md += fmt::format("{} recording(s), {} samples at {:g} Hz ({:.2f} h). Intervals at {:g} %; method: docs/noise.md.\n\n",
                    rec.runs.size(), rec.size(), 1 / rec.dt_s, total_s / 3600, 100 * confidence);

  md += fmt::format("## Against Table 3.1\n\nEach term as a constant error over one Schuler period ({:.1f} min), "
                    "root-sum-square over the terms, against Table 3.1's bound (gyros: drift ω_do < {}; "
                    "accelerometers: bias change ∂f < {}). The terms are the fitted model's where it passes its fit "
                    "test, else the IEEE slope readings (column \"from\"). A verdict only where the data hold a "
                    "stretch of one Schuler period; over shorter data the ratio is an extrapolation and says how "
                    "far.\n\n",
                    schuler_period_s() / 60, table31_bound_text(SensorKind::kGyro),
                    table31_bound_text(SensorKind::kAccelerometer));
  md += "| channel | equivalent | bound | ratio | verdict | from | largest term |\n|---|---:|---:|---:|---|---|---|\n";
  for (const ChannelNoise& ch : a.channels) {
    const Table31Reading t = table31_reading(ch);
    const bool gyro = ch.kind == SensorKind::kGyro;
    if (t.source == Table31Source::kStuck) {
      md += fmt::format("| {} | - | {} | - | **stuck: the output never changes**, no noise measured (a dead or "
                        "saturated channel, or a constant column) | - | - |\n",
                        ch.name, table31_bound_text(ch.kind));
      continue;
    }
    const std::string verdict =
        t.extrapolated ? fmt::format("no verdict: extrapolated {:.3g}× beyond the longest stretch of data ({:.3g} s; "
                                     "longest τ {:.3g} s)",
                                     t.extrapolation, ch.longest_stretch_s, ch.allan.empty() ? 0.0 : ch.allan.back().tau_s)
        : t.ratio > 1 ? "**above**"
                      : "within";
    md += fmt::format("| {} | {} {} | {} | {:.3g}× | {} | {} | {} |\n", ch.name,
                      g3(t.equivalent_si / (gyro ? kMeruToRadps : kMgToMps2)), gyro ? "meru" : "mg",
                      table31_bound_text(ch.kind), t.ratio, verdict,
                      t.source == Table31Source::kFit ? "fit" : "IEEE readings", t.largest_term);
  }

  md += readings_section(a, sheet);
  if (!sheet.empty()) md += datasheet_section(a, sheet);

  md += fit_test_section(a);
  md += "\n## Fitted terms\n\nThe models that pass their fit test (above), each term with its interval.\n\n"
        "| channel | term | value | interval | unit | value (SI) | unit (SI) |\n|---|---|---:|---|---|---:|---|\n";
  for (const ChannelNoise& ch : a.channels) {
    if (!ch.fit.fits || ch.stuck) continue;
    for (const TermFit& t : ch.fit.terms) {
      const auto [v, unit] = spec_value(t.term, ch.kind, t.value_si);
      const double f = t.value_si > 0 ? v / t.value_si : 0;
      md += fmt::format("| {} | {} | {} | [{}, {}] | {} | {} | {} |\n", ch.name, term_name(t.term, ch.kind), g3(v),
                        g3(t.lower_si * f), g3(t.upper_si * f), unit, g3(t.value_si), term_si_unit(t.term, ch.kind));
      if (t.term == NoiseTerm::kGaussMarkov)
        md += fmt::format("| {} | correlation time | {} | [{}, {}] | s | {} | s |\n", ch.name, g3(ch.fit.model.correlation_time_s),
                          g3(ch.fit.correlation_time_lower_s), g3(ch.fit.correlation_time_upper_s),
                          g3(ch.fit.model.correlation_time_s));
    }
  }
  for (const ChannelNoise& ch : a.channels) {
    const auto white = std::find_if(ch.fit.terms.begin(), ch.fit.terms.end(),
                                    [](const TermFit& t) { return t.term == NoiseTerm::kWhiteRate; });
    if (white == ch.fit.terms.end()) continue;
    if (const std::optional<WhiteTogether> together = white_together(ch, *white)) {
      const auto [v, unit] = spec_value(NoiseTerm::kWhiteRate, ch.kind, together->value_si);
      const double f = v / together->value_si;
      md += fmt::format("\n{}: the Gauss–Markov term has T_c at the sampling interval ({:g} s), the sensor's own "
                        "bandwidth; beyond a few samples it is white noise, and together with the random-walk term N it "
                        "makes {} {} [{}, {}] of white noise, √(N² + 2σ²T_c) (the interval from each term's own "
                        "interval's ends: at least the stated confidence).\n",
                        ch.name, ch.fit.model.correlation_time_s, g3(v), unit, g3(together->lower_si * f),
                        g3(together->upper_si * f));
    }
  }
  md += "\nTerms tried and not needed (their likelihood-ratio statistic below the test's critical value):\n";
  for (const ChannelNoise& ch : a.channels) {
    if (!ch.fit.fits || ch.stuck) continue;
    std::string dropped;
    for (const TermFit& t : ch.fit.dropped)
      dropped += fmt::format("{}{} ({:.2g})", dropped.empty() ? "" : ", ", term_name(t.term, ch.kind), t.drop_statistic);
    md += fmt::format("- {}: {}\n", ch.name, dropped.empty() ? "none" : dropped);
  }

  md += "\n## Stationarity: the first part of each run against the rest\n\n";
  md += "The mean over the first part minus the mean over the rest of the run, against its standard deviation under "
        "the rest's noise model ((N.6), docs/noise.md §5), Σ z² over the runs against χ²(runs).\n\n";
  md += "| channel | first part | first part − rest | expected sd | runs | χ² | p | verdict |\n|---|---:|---:|---:|---:|---:|---:|---|\n";
  for (const ChannelNoise& ch : a.channels) {
    const StationarityTest& s = ch.stationarity;
    if (!s.tested) {
      md += fmt::format("| {} | - | - | - | 0 | - | - | not tested (no run twice as long as the first part) |\n", ch.name);
      continue;
    }
    const bool gyro = ch.kind == SensorKind::kGyro;
    const double unit = gyro ? kDegphToRadps : kUgToMps2;
    md += fmt::format("| {} | {:.3g} min | {} {} | {} {} | {} | {:.3g} | {:.2g} | {} |\n", ch.name, s.first_part_s / 60,
                      g3(s.mean_change / unit), gyro ? "deg/h" : "ug", g3(s.expected_sd / unit), gyro ? "deg/h" : "ug",
                      s.runs, s.statistic, s.p_value,
                      s.stationary ? "stationary" : "**non-stationary (warm-up): left out of the fit**");
  }

  md += "\n## Masked disturbances\n\n";
  if (a.mask.intervals.empty()) {
    md += fmt::format("None found (blocks of {:g} s tested for excess variance and for jumps of the mean).\n", a.mask.block_s);
  } else {
    md += fmt::format("{} interval(s), {:.1f} s in all, each left out of the channels of the sensor that felt it (the "
                      "gyros lose {:.1f} s, the accelerometers {:.1f} s):\n\n| recording | from [s] | to [s] | "
                      "channels | test | excess | cut from |\n|---|---:|---:|---|---|---:|---|\n",
                      a.mask.intervals.size(), static_cast<double>(a.mask.masked_samples) * rec.dt_s,
                      static_cast<double>(a.mask.masked_by_sensor[0]) * rec.dt_s,
                      static_cast<double>(a.mask.masked_by_sensor[1]) * rec.dt_s);
    for (const MaskedInterval& m : a.mask.intervals)
      md += fmt::format("| {} | {:.1f} | {:.1f} | {} | {} | {:.3g}× | {} |\n", rec.run_names[m.run], m.start_s,
                        m.end_s, m.channels, m.test, m.excess, m.sensors);
  }
  md += "\n## What these data can identify\n\n" + identifiability(orientations(rec, a), calibrations);
  md += calibration_markdown(calibrations, confidence);
  return md;
}

std::string allan_csv(const NoiseAnalysis& a) {
  std::string csv = "channel,tau_s,adev_si,adev_lower_si,adev_upper_si,edf,windows,model_adev_si,si_unit\n";
  for (const ChannelNoise& ch : a.channels)
    for (const AllanRow& r : ch.allan)
      csv += fmt::format("{},{},{},{},{},{:.6g},{},{},{}\n", ch.name, r.tau_s, r.adev, r.lower, r.upper, r.edf, r.windows,
                         r.model_adev, ch.kind == SensorKind::kGyro ? "rad/s" : "m/s2");
  return csv;
}

std::string terms_csv(const NoiseAnalysis& a) {
  std::string csv = "channel,term,value_si,lower_si,upper_si,si_unit,value_spec,lower_spec,upper_spec,spec_unit\n";
  for (const ChannelNoise& ch : a.channels)
    for (const TermFit& t : ch.fit.terms) {
      const auto [v, unit] = spec_value(t.term, ch.kind, t.value_si);
      const double f = t.value_si > 0 ? v / t.value_si : 0;
      csv += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", ch.name, term_name(t.term, ch.kind), t.value_si,
                         t.lower_si, t.upper_si, term_si_unit(t.term, ch.kind), v, t.lower_si * f, t.upper_si * f, unit);
      if (t.term == NoiseTerm::kGaussMarkov)
        csv += fmt::format("{},correlation_time,{},{},{},s,{},{},{},s\n", ch.name, ch.fit.model.correlation_time_s,
                           ch.fit.correlation_time_lower_s, ch.fit.correlation_time_upper_s,
                           ch.fit.model.correlation_time_s, ch.fit.correlation_time_lower_s,
                           ch.fit.correlation_time_upper_s);
    }
  return csv;
}

mc::Json noise_json(const SensorRecording& rec, const NoiseAnalysis& a, double confidence,
                const Datasheet& sheet, const std::vector<RecordingCalibration>& calibrations) {
  mc::Json j = mc::Json::object();
  j["sample_interval_s"] = rec.dt_s;
  j["samples"] = rec.size();
  j["recordings"] = rec.runs.size();
  j["confidence"] = confidence;
  mc::Json channels = mc::Json::array();
  for (const ChannelNoise& ch : a.channels) {
    mc::Json c = mc::Json::object();
    c["channel"] = ch.name;
    mc::Json terms = mc::Json::array();
    for (const TermFit& t : ch.fit.terms) {
      mc::Json x = mc::Json::object();
      const auto [v, unit] = spec_value(t.term, ch.kind, t.value_si);
      const double f = t.value_si > 0 ? v / t.value_si : 0;
      x["term"] = std::string(term_name(t.term, ch.kind));
      x["value_si"] = t.value_si, x["lower_si"] = t.lower_si, x["upper_si"] = t.upper_si;
      x["si_unit"] = std::string(term_si_unit(t.term, ch.kind));
      x["value_spec"] = v, x["lower_spec"] = t.lower_si * f, x["upper_spec"] = t.upper_si * f, x["spec_unit"] = unit;
      if (t.term == NoiseTerm::kGaussMarkov) {
        x["correlation_time_s"] = ch.fit.model.correlation_time_s;
        x["correlation_time_lower_s"] = ch.fit.correlation_time_lower_s;
        x["correlation_time_upper_s"] = ch.fit.correlation_time_upper_s;
      }
      terms.push_back(std::move(x));
    }
    c["terms"] = std::move(terms);
    c["stuck"] = ch.stuck;
    mc::Json test = mc::Json::object();
    test["statistic"] = ch.fit.fit_statistic, test["dof"] = ch.fit.fit_dof, test["p_value"] = ch.fit.fit_p_value;
    test["passes"] = ch.fit.fits && !ch.stuck;
    test["first_tau_s"] = ch.allan.empty() ? 0.0 : ch.allan[std::min(ch.fit.first_level, ch.allan.size() - 1)].tau_s;
    c["fit_test"] = std::move(test);
    mc::Json readings = mc::Json::object();
    for (const auto& [name, r] : {std::pair{"white_si", &ch.readings.white},
                                  std::pair{"bias_instability_si", &ch.readings.instability},
                                  std::pair{"rate_random_walk_si", &ch.readings.walk}})
      if (r->found) readings[name] = r->value_si;
    c["ieee_readings"] = std::move(readings);
    const Table31Reading t31 = table31_reading(ch);
    mc::Json table31 = mc::Json::object();
    table31["from"] = std::string(table31_source_text(t31.source));
    table31["equivalent_si"] = t31.equivalent_si, table31["ratio"] = t31.ratio;
    table31["extrapolated"] = t31.extrapolated, table31["extrapolation"] = t31.extrapolation;
    c["table31"] = std::move(table31);
    if (const auto n_eff = white_noise_effective(ch)) c["white_noise_effective_si"] = *n_eff;
    mc::Json st = mc::Json::object();
    st["tested"] = ch.stationarity.tested;
    st["first_part_s"] = ch.stationarity.first_part_s;
    st["mean_change_si"] = ch.stationarity.mean_change;
    st["expected_sd_si"] = ch.stationarity.expected_sd;
    st["p_value"] = ch.stationarity.p_value;
    st["stationary"] = ch.stationarity.stationary;
    st["first_part_excluded"] = ch.first_part_excluded;
    c["stationarity"] = std::move(st);
    mc::Json allan = mc::Json::array();
    for (const AllanRow& r : ch.allan) {
      mc::Json x = mc::Json::object();
      x["tau_s"] = r.tau_s, x["adev_si"] = r.adev, x["lower_si"] = r.lower, x["upper_si"] = r.upper, x["edf"] = r.edf;
      x["model_adev_si"] = r.model_adev;
      allan.push_back(std::move(x));
    }
    c["allan"] = std::move(allan);
    channels.push_back(std::move(c));
  }
  j["channels"] = std::move(channels);
  mc::Json masked = mc::Json::array();
  for (const MaskedInterval& m : a.mask.intervals) {
    mc::Json x = mc::Json::object();
    x["recording"] = rec.run_names[m.run], x["start_s"] = m.start_s, x["end_s"] = m.end_s;
    x["channels"] = m.channels, x["test"] = m.test, x["excess"] = m.excess, x["sensors"] = m.sensors;
    masked.push_back(std::move(x));
  }
  j["masked"] = std::move(masked);
  mc::Json given = mc::Json::object();
  if (sheet.gyro_arw_radprts) given["gyro_arw_radprts"] = *sheet.gyro_arw_radprts;
  if (sheet.gyro_bias_instability_radps) given["gyro_bias_instability_radps"] = *sheet.gyro_bias_instability_radps;
  if (sheet.accel_vrw_mpsprts) given["accel_vrw_mpsprts"] = *sheet.accel_vrw_mpsprts;
  if (sheet.accel_bias_instability_mps2) given["accel_bias_instability_mps2"] = *sheet.accel_bias_instability_mps2;
  j["datasheet"] = std::move(given);
  j["calibration"] = calibration_json(calibrations);
  return j;
}

}  // namespace

std::optional<double> Datasheet::white(SensorKind kind) const {
  return kind == SensorKind::kGyro ? gyro_arw_radprts : accel_vrw_mpsprts;
}

std::optional<double> Datasheet::instability(SensorKind kind) const {
  return kind == SensorKind::kGyro ? gyro_bias_instability_radps : accel_bias_instability_mps2;
}

void parse_datasheet_entry(const std::string& text, Datasheet& sheet) {
  struct Key {
    const char* name;
    Dimension dimension;
    std::optional<double> Datasheet::*slot;
  };
  static const Key kKeys[] = {{"gyro_arw", Dimension::kAngleRandomWalk, &Datasheet::gyro_arw_radprts},
                              {"gyro_bias_instability", Dimension::kAngularRate, &Datasheet::gyro_bias_instability_radps},
                              {"accel_vrw", Dimension::kVelocityRandomWalk, &Datasheet::accel_vrw_mpsprts},
                              {"accel_bias_instability", Dimension::kAcceleration, &Datasheet::accel_bias_instability_mps2}};
  const std::size_t eq = text.find('=');
  const std::string key = eq == std::string::npos ? text : text.substr(0, eq);
  for (const Key& k : kKeys) {
    if (key != k.name) continue;
    const double v = parse_quantity(text.substr(eq + 1), k.dimension, "--datasheet " + key);
    // A data sheet states a noise level; zero is no statement (and would
    // leave nothing to compare the fit with).
    require_in_range("--datasheet " + key, v, k.dimension, {0.0, magnitude_limit(k.dimension), true});
    sheet.*k.slot = v;
    return;
  }
  throw InputError("--datasheet", echo_input(text),
                   "must be KEY=VALUE with KEY gyro_arw (e.g. 0.15degprth), gyro_bias_instability (1degph), "
                   "accel_vrw (0.03mpsprth) or accel_bias_instability (50ug)");
}

mc::ReportOutline noise_report_outline() {
  return {"noise",
          {"noise.md", "allan.csv", "noise_terms.csv", "calibration.csv", "noise.json"},
          {"allan", "stationarity"},
          {mc::ReportFormat::kMarkdown, mc::ReportFormat::kJson}};
}

mc::Report noise_report(const SensorRecording& rec, const NoiseAnalysis& a, double confidence,
                    const Datasheet& sheet, const std::vector<RecordingCalibration>& calibrations) {
  std::string md = markdown(rec, a, confidence, sheet, calibrations);
  std::string json = noise_json(rec, a, confidence, sheet, calibrations).dump(2) + "\n";
  const std::array<SheetLevels, 2> levels{
      SheetLevels{sheet.white(SensorKind::kGyro), sheet.instability(SensorKind::kGyro)},
      SheetLevels{sheet.white(SensorKind::kAccelerometer), sheet.instability(SensorKind::kAccelerometer)}};
  mc::Report report(noise_report_outline());
  report.file("noise.md", std::move(md))
      .file("allan.csv", allan_csv(a))
      .file("noise_terms.csv", terms_csv(a))
      .file("calibration.csv", calibration_csv(calibrations))
      .file("noise.json", std::move(json))
      .figure("allan", [figure = noise_allan_figure(a, levels)] { return render_panel_figure(figure); })
      .figure("stationarity", [figure = stationarity_figure(rec, a)] { return render_panel_figure(figure); })
      .shown_file(mc::ReportFormat::kMarkdown, "noise.md")
      .shown_file(mc::ReportFormat::kJson, "noise.json");
  return report;
}

void require_noise_samples(const ImuSamples& recording) {
  if (recording.size() < kMinNoiseSamples)
    throw InputError("--input", recording.source,  // the file name as given, made one-line
                     fmt::format("{} samples: a noise analysis needs at least {} per recording", recording.size(),
                                 kMinNoiseSamples));
}

mc::Report noise_stage(std::vector<ImuSamples> recordings, const NoiseStageOptions& options) {
  for (const ImuSamples& r : recordings) require_noise_samples(r);
  const SensorRecording rec = make_recording(recordings);
  std::vector<RecordingCalibration> calibrations;
  for (const ImuSamples& r : recordings)
    calibrations.push_back(
        {r.source, calibration::calibrate_multiposition(r, options.calibration), options.calibration.gravity_mps2});
  recordings.clear();  // the recording holds the samples now
  const NoiseAnalysis analysis = analyse_noise(rec, options.analysis);
  return noise_report(rec, analysis, options.analysis.confidence, options.sheet, calibrations);
}

}  // namespace insmc::noise
