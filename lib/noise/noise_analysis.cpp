#include "lib/noise/noise_analysis.h"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

#include "lib/common/input_error.h"

namespace insmc::noise {
namespace {

std::vector<AllanRow> allan_rows(const std::vector<AllanLevel>& levels, const NoiseFit& fit, double confidence) {
  std::vector<AllanRow> rows;
  for (std::size_t j = 0; j < levels.size(); ++j) {
    AllanRow r;
    r.tau_s = levels[j].tau_s;
    r.adev = std::sqrt(levels[j].avar);
    r.edf = fit.edf[j];
    const DeviationInterval ci = adev_interval(levels[j].avar, r.edf, confidence);
    r.lower = ci.lo, r.upper = ci.hi;
    // The model only where it was fitted (the levels before first_level lie
    // outside every model that passes, docs/noise.md §3).
    r.model_adev = j >= fit.first_level ? std::sqrt(fit.model.avar(r.tau_s)) : 0.0;
    r.windows = levels[j].windows;
    rows.push_back(r);
  }
  return rows;
}

std::size_t total(std::span<const Segment> s) {
  std::size_t n = 0;
  for (const Segment& x : s) n += x.size();
  return n;
}

}  // namespace

NoiseAnalysis analyse_noise(const SensorRecording& rec, const NoiseOptions& options) {
  NoiseAnalysis out;
  out.dt_s = rec.dt_s;
  out.alpha = options.alpha;
  out.confidence = options.confidence;
  const auto tell = [&](std::string_view stage, std::size_t done) {
    if (options.progress) options.progress(stage, done, kChannels);
  };
  tell("disturbance mask", 0);
  out.mask = options.mask ? find_disturbances(rec, options.alpha) : no_mask(rec);
  out.used_s = static_cast<double>(total(out.mask.kept)) * rec.dt_s;
  std::size_t longest = 0;
  for (const Segment& r : rec.runs) longest = std::max(longest, r.size());
  const double first_part_s =
      std::min(options.first_part_s, static_cast<double>(longest) * rec.dt_s / 2);
  NoiseFitOptions fit_options;
  fit_options.selection_alpha = options.alpha;
  fit_options.confidence = options.confidence;
  for (std::size_t c = 0; c < kChannels; ++c) {
    tell("Allan deviation and fit per channel", c);
    ChannelNoise& ch = out.channels[c];
    ch.name = channel_name(c);
    ch.kind = channel_kind(c);
    // Masked where this channel's own sensor was disturbed.
    const std::vector<Segment>& kept = out.mask.kept_for(ch.kind);
    const std::vector<Segment> rest = after_first_part(rec.runs, kept, rec.dt_s, first_part_s);
    const std::vector<double>& y = rec.channel[c];
    const std::vector<AllanLevel> rest_levels =
        first_part_s > 0 ? overlapping_allan(y, rec.dt_s, rest) : std::vector<AllanLevel>{};
    if (rest_levels.size() >= 2) {
      const NoiseFit rest_fit = fit_noise(rest_levels, fit_options);
      const bool constant = std::all_of(y.begin(), y.end(), [&](double v) { return v == y.front(); });
      if (!constant)
        ch.stationarity = test_first_part(y, rec.dt_s, rec.runs, kept, rest_fit.model, first_part_s, options.alpha);
    }
    ch.first_part_excluded = ch.stationarity.tested && !ch.stationarity.stationary;
    const std::vector<Segment>& used = ch.first_part_excluded ? rest : kept;
    const std::vector<AllanLevel> levels = overlapping_allan(y, rec.dt_s, used);
    if (levels.size() < 2) {
      // A property of the data, not a defect: say what was left and why.
      std::size_t kept = 0, longest_kept = 0;
      for (const Segment& s : used) kept += s.size(), longest_kept = std::max(longest_kept, s.size());
      throw InputError(
          "--input", fmt::format("{} ({} samples)", ch.name, rec.size()),
          fmt::format("after {}{} the longest undisturbed stretch holds {} samples ({} in all): too few for two "
                      "Allan cluster times; record longer{}",
                      options.mask ? "masking disturbances" : "taking every sample",
                      ch.first_part_excluded ? " and leaving out the warm-up" : "", longest_kept, kept,
                      options.mask ? ", or give --mask off" : ""));
    }
    for (const Segment& s : used)
      ch.longest_stretch_s = std::max(ch.longest_stretch_s, static_cast<double>(s.size()) * rec.dt_s);
    // Stuck: every sample the fit uses holds one value (its Allan variance is
    // rounding in the running sums, not noise).
    ch.stuck = true;
    for (const Segment& s : used)
      for (std::size_t k = s.begin; k < s.end && ch.stuck; ++k) ch.stuck = y[k] == y[used.front().begin];
    ch.fit = fit_noise(levels, fit_options);
    ch.allan = allan_rows(levels, ch.fit, options.confidence);
    ch.readings = read_slopes(ch.allan);
  }
  tell("Allan deviation and fit per channel", kChannels);
  return out;
}

}  // namespace insmc::noise
