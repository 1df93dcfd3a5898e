#include "montecarlo/study/rank/scheme_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "montecarlo/study/random/philox.h"

namespace insmc::mc {
namespace {

/// (mean d, its standard error) of d_s = a_s² − b_s² over the kept samples.
std::pair<double, double> paired_difference(const std::vector<float>& a, const std::vector<float>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n < 2) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  double sum = 0, sum2 = 0;
  for (std::size_t s = 0; s < n; ++s) {
    const double d = double(a[s]) * a[s] - double(b[s]) * b[s];
    sum += d;
    sum2 += d * d;
  }
  const double mean = sum / double(n), var = std::max(0.0, (sum2 - sum * mean) / double(n - 1));
  return {mean, std::sqrt(var / double(n))};
}

}  // namespace

std::vector<SchemeOrder> order_schemes(const StudyConfig& config, const StudyLayout& layout,
                                       const StudyAccumulator& state) {
  const double z_crit = inverse_normal_cdf(0.5 + config.confidence / 2);
  std::vector<SchemeOrder> out;
  for (int j = 0; j < layout.n_systems; ++j) {
    for (int k = 0; k < layout.n_times; ++k) {
      // At t = 0 nothing has propagated yet: every scheme shows its initial error.
      if (layout.times_s[static_cast<std::size_t>(k)] <= 0) continue;
      const bool paired = layout.is_report_time[static_cast<std::size_t>(k)];
      SchemeOrder order{config.systems[static_cast<std::size_t>(j)], layout.times_s[static_cast<std::size_t>(k)], paired, 0, {}};
      std::vector<std::vector<float>> kept;
      for (std::size_t i = 0; i < config.schemes.size(); ++i) {
        const auto o = static_cast<std::size_t>(layout.index(static_cast<int>(i), j, k, Axis::kHorizontal));
        const OutputSummary s = state.outputs()[o].summarize(config.confidence);
        order.schemes.push_back({config.schemes[i], s.rms, s.rms_lo, s.rms_hi, false, 0.0});
        if (paired) kept.push_back(state.kept().values(static_cast<std::uint64_t>(layout.kept_slot[o])));
      }
      std::vector<std::size_t> by_rms(order.schemes.size());
      std::iota(by_rms.begin(), by_rms.end(), std::size_t{0});
      std::stable_sort(by_rms.begin(), by_rms.end(),
                       [&](std::size_t a, std::size_t b) { return order.schemes[a].rms_m < order.schemes[b].rms_m; });
      std::vector<RankedScheme> sorted;
      for (std::size_t r = 0; r < by_rms.size(); ++r) {
        RankedScheme s = order.schemes[by_rms[r]];
        if (r + 1 < by_rms.size() && paired) {
          const auto [mean, se] = paired_difference(kept[by_rms[r + 1]], kept[by_rms[r]]);
          s.paired_z = se > 0 ? mean / se : (mean > 0 ? std::numeric_limits<double>::infinity() : 0.0);
          s.order_significant = std::isfinite(mean) && s.paired_z > z_crit;
        } else if (r + 1 < by_rms.size()) {
          s.paired_z = std::numeric_limits<double>::quiet_NaN();
          s.order_significant = s.rms_hi_m < order.schemes[by_rms[r + 1]].rms_lo_m;
        }
        sorted.push_back(s);
      }
      order.paired_samples = kept.empty() ? 0 : kept.front().size();
      order.schemes = std::move(sorted);
      out.push_back(std::move(order));
    }
  }
  return out;
}

}  // namespace insmc::mc
