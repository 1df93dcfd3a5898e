#include "lib/noise/disturbances.h"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>

namespace insmc::noise {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

constexpr std::size_t kRunningMedianHalfWidth = 15;  ///< 31 blocks

struct Flag {
  bool variance = false, mean = false;
  std::array<bool, 2> sensor{};  ///< flagged by a gyro, by an accelerometer
  double excess = 0;
  std::string channels;
};

}  // namespace

DisturbanceMask no_mask(const SensorRecording& rec) {
  DisturbanceMask m;
  m.kept = rec.runs;
  m.kept_by_sensor = {rec.runs, rec.runs};
  return m;
}

namespace {

/// The run with the masked blocks (of n samples) cut out, appended to
/// `kept`; returns the samples masked. The last block also takes the
/// samples after it (fewer than a block).
std::size_t cut(const Segment& run, const std::vector<bool>& masked, std::size_t n, std::vector<Segment>& kept) {
  const std::size_t blocks = masked.size();
  std::size_t kept_from = run.begin, lost = 0;
  for (std::size_t i = 0; i < blocks;) {
    if (!masked[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < blocks && masked[j]) ++j;
    const std::size_t end_sample = j == blocks ? run.size() : j * n;
    if (run.begin + i * n > kept_from) kept.push_back({kept_from, run.begin + i * n});
    kept_from = run.begin + end_sample;
    lost += end_sample - i * n;
    i = j;
  }
  if (run.end > kept_from) kept.push_back({kept_from, run.end});
  return lost;
}

}  // namespace

DisturbanceMask find_disturbances(const SensorRecording& rec, double alpha) {
  DisturbanceMask out;
  const std::size_t n = std::max<std::size_t>(10, static_cast<std::size_t>(std::ceil(1.0 / rec.dt_s - 1e-9)));
  out.block_s = static_cast<double>(n) * rec.dt_s;
  std::size_t total_blocks = 0;
  for (const Segment& run : rec.runs) total_blocks += run.size() / n;
  if (total_blocks < 2 * kRunningMedianHalfWidth + 1) return no_mask(rec);
  const double a = alpha / static_cast<double>(total_blocks * kChannels);
  const double nu = static_cast<double>(n - 1);
  const double z_limit = boost::math::quantile(boost::math::normal(), 1 - a / 2);
  const double z_limit_one_sided = boost::math::quantile(boost::math::normal(), 1 - a);

  // Per run and block: the flags.
  std::vector<std::vector<Flag>> flags(rec.runs.size());
  for (std::size_t r = 0; r < rec.runs.size(); ++r) flags[r].resize(rec.runs[r].size() / n);
  for (std::size_t c = 0; c < kChannels; ++c) {
    const std::vector<double>& y = rec.channel[c];
    std::vector<std::vector<double>> means(rec.runs.size()), vars(rec.runs.size());
    std::vector<double> all_vars, all_departures;
    std::vector<std::vector<double>> departures(rec.runs.size());
    for (std::size_t r = 0; r < rec.runs.size(); ++r) {
      const std::size_t blocks = flags[r].size();
      for (std::size_t i = 0; i < blocks; ++i) {
        const std::size_t b = rec.runs[r].begin + i * n;
        double mean = 0, ss = 0;
        for (std::size_t k = 0; k < n; ++k) mean += y[b + k];
        mean /= static_cast<double>(n);
        for (std::size_t k = 0; k < n; ++k) ss += (y[b + k] - mean) * (y[b + k] - mean);
        means[r].push_back(mean);
        vars[r].push_back(ss / nu);
        all_vars.push_back(ss / nu);
      }
      for (std::size_t i = 0; i < blocks; ++i) {
        const std::size_t lo = i >= kRunningMedianHalfWidth ? i - kRunningMedianHalfWidth : 0;
        const std::size_t hi = std::min(blocks, i + kRunningMedianHalfWidth + 1);
        const double d = means[r][i] - median({means[r].begin() + static_cast<std::ptrdiff_t>(lo),
                                               means[r].begin() + static_cast<std::ptrdiff_t>(hi)});
        departures[r].push_back(d);
        all_departures.push_back(std::abs(d));
      }
    }
    // ln s² of each block against the channel's median and robust spread:
    // real sensor noise is rarely Gaussian (quantized, heavy tailed), so the
    // spread of ln s² is measured, not taken from χ²(n−1).
    std::vector<double> log_vars, log_dev;
    for (double v : all_vars) log_vars.push_back(std::log(std::max(v, 1e-300)));
    const double log_median = median(log_vars);
    for (double v : log_vars) log_dev.push_back(std::abs(v - log_median));
    const double log_sd = 1.4826 * median(log_dev);
    const double robust_sd = 1.4826 * median(all_departures);
    for (std::size_t r = 0; r < rec.runs.size(); ++r)
      for (std::size_t i = 0; i < flags[r].size(); ++i) {
        Flag& f = flags[r][i];
        const double v_excess =
            log_sd > 0 && vars[r][i] > 0
                ? std::exp(std::log(vars[r][i]) - log_median) / std::exp(z_limit_one_sided * log_sd)
                : 0;
        const double m_excess = robust_sd > 0 ? std::abs(departures[r][i]) / (robust_sd * z_limit) : 0;
        if (v_excess > 1 || m_excess > 1) {
          f.variance = f.variance || v_excess > 1;
          f.mean = f.mean || m_excess > 1;
          f.excess = std::max({f.excess, v_excess, m_excess});
          f.channels += (f.channels.empty() ? "" : ",") + channel_name(c);
          f.sensor[static_cast<std::size_t>(channel_kind(c))] = true;
        }
      }
  }

  for (std::size_t r = 0; r < rec.runs.size(); ++r) {
    const Segment run = rec.runs[r];
    const std::size_t blocks = flags[r].size();
    // A flagged block and one on each side: in the flagging sensor's channels
    // (per sensor), in the union for the report's intervals.
    std::vector<bool> masked(blocks, false);
    std::array<std::vector<bool>, 2> by_sensor{std::vector<bool>(blocks, false), std::vector<bool>(blocks, false)};
    for (std::size_t i = 0; i < blocks; ++i)
      for (std::size_t j = i > 0 ? i - 1 : 0; !flags[r][i].channels.empty() && j <= std::min(blocks - 1, i + 1); ++j) {
        masked[j] = true;
        for (std::size_t k = 0; k < 2; ++k) by_sensor[k][j] = by_sensor[k][j] || flags[r][i].sensor[k];
      }
    out.masked_samples += cut(run, masked, n, out.kept);
    for (std::size_t k = 0; k < 2; ++k) out.masked_by_sensor[k] += cut(run, by_sensor[k], n, out.kept_by_sensor[k]);
    for (std::size_t i = 0; i < blocks;) {
      if (!masked[i]) {
        ++i;
        continue;
      }
      std::size_t j = i;
      MaskedInterval mi;
      mi.run = r;
      bool var = false, mean = false;
      std::array<bool, 2> sensor{};
      std::vector<std::string> chans;
      for (; j < blocks && masked[j]; ++j) {
        const Flag& f = flags[r][j];
        var = var || f.variance, mean = mean || f.mean;
        for (std::size_t k = 0; k < 2; ++k) sensor[k] = sensor[k] || by_sensor[k][j];
        mi.excess = std::max(mi.excess, f.excess);
        std::size_t p = 0;
        while (p < f.channels.size()) {
          const std::size_t q = std::min(f.channels.find(',', p), f.channels.size());
          const std::string name = f.channels.substr(p, q - p);
          if (std::find(chans.begin(), chans.end(), name) == chans.end()) chans.push_back(name);
          p = q + 1;
        }
      }
      for (const std::string& ch : chans) mi.channels += (mi.channels.empty() ? "" : ",") + ch;
      mi.test = var && mean ? "variance,mean" : var ? "variance" : "mean";
      mi.sensors = sensor[0] && sensor[1] ? "gyros,accelerometers" : sensor[0] ? "gyros" : "accelerometers";
      mi.start_s = static_cast<double>(i * n) * rec.dt_s;
      mi.end_s = static_cast<double>(j == blocks ? run.size() : j * n) * rec.dt_s;
      out.intervals.push_back(mi);
      i = j;
    }
  }
  return out;
}

}  // namespace insmc::noise
