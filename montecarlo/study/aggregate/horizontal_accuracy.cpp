#include "montecarlo/study/aggregate/horizontal_accuracy.h"

#include <limits>

namespace insmc::mc {

HorizontalAccuracy horizontal_accuracy(const OutputSummary& h, std::vector<float> radial_m, double t_s,
                                       double confidence) {
  HorizontalAccuracy a;
  a.quantile_samples = radial_m.size();
  // The radial error is a magnitude: rank 0 of an interval stands for 0 m.
  a.cep50_m = quantile_with_interval(radial_m, 0.50, confidence, 0.0);
  a.cep95_m = quantile_with_interval(radial_m, 0.95, confidence, 0.0);
  // 2DRMS = 2·RMS of r, and its interval twice the RMS interval.
  a.drms2_m = {2 * h.rms, 2 * h.rms_lo, 2 * h.rms_hi};
  // Rate = CEP50(t) / t: t is exact, so the interval scales with it.
  const double inv_t = t_s > 0 ? 1 / t_s : std::numeric_limits<double>::quiet_NaN();
  a.radial_rate_mps = {a.cep50_m.value * inv_t, a.cep50_m.lo * inv_t, a.cep50_m.hi * inv_t};
  return a;
}

}  // namespace insmc::mc
