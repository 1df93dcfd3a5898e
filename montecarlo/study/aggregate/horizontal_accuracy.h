#pragma once
/// The navigation accuracy metrics of a horizontal output, from its samples
/// (docs/outputs.md, "Accuracy metrics"): CEP50 and CEP95, the 50th and 95th
/// percentiles of the radial error r = sqrt(N² + E²) with order-statistic
/// intervals (order_statistics.h); 2DRMS = 2·sqrt(mean r²) with the RMS
/// interval of output_stats.h doubled; and the radial error rate CEP50(t)/t.
/// SI: metres, and metres per second for the rate.
#include <cstdint>
#include <vector>

#include "montecarlo/study/aggregate/order_statistics.h"
#include "montecarlo/study/aggregate/output_stats.h"

namespace insmc::mc {

struct HorizontalAccuracy {
  std::uint64_t quantile_samples = 0;  ///< the kept samples the quantiles come from (kept_samples.h)
  QuantileEstimate cep50_m{}, cep95_m{}, drms2_m{};
  QuantileEstimate radial_rate_mps{};  ///< CEP50 / t and its interval; NaN at t = 0
};

/// `horizontal`: the horizontal output's summary (at the same confidence);
/// `radial_m`: its kept per-sample radial errors (reordered); `t_s`: the
/// output's time on its scheme's clock.
HorizontalAccuracy horizontal_accuracy(const OutputSummary& horizontal, std::vector<float> radial_m, double t_s,
                                       double confidence);

}  // namespace insmc::mc
