#pragma once
/// The schemes in order of their horizontal RMS, per system and report time,
/// from a Monte Carlo run, with the significance of each adjacent pair's
/// order from the same samples (paired): every scheme of a sample sees the
/// same uncertainties, so the difference of two schemes' squared errors,
/// d = r_a² − r_b², has mean RMS_a² − RMS_b² and a standard error from the
/// samples' own scatter of d, far smaller than the two RMS intervals
/// suggest. The pair's order is significant when |mean d| exceeds the
/// two-sided normal quantile of the study's confidence times that error
/// (the CLT over the kept samples, engine.h: the first ≤ 2^24 values).
/// The samples are kept at the report times only; on the envelope grid the
/// order is tested unpaired and conservatively: significant when the two
/// RMS intervals do not overlap.
#include <vector>

#include "montecarlo/study/engine/engine.h"

namespace insmc::mc {

struct RankedScheme {
  Scheme scheme;
  double rms_m = 0, rms_lo_m = 0, rms_hi_m = 0;  ///< horizontal RMS and its interval (all samples)
  /// Against the next scheme in the order (false for the last): the paired
  /// test of RMS² difference, z its statistic (NaN when not computable); on
  /// the grid, disjoint RMS intervals (z NaN).
  bool order_significant = false;
  double paired_z = 0;
};

struct SchemeOrder {
  System system;
  double t_s = 0;
  bool paired = false;             ///< a report time (paired test), else a grid time (intervals)
  std::size_t paired_samples = 0;  ///< samples of the paired tests
  std::vector<RankedScheme> schemes;  ///< best (smallest RMS) first
};

/// One order per system and time of the layout after t = 0, report times
/// and the grid (config order, then time).
std::vector<SchemeOrder> order_schemes(const StudyConfig& config, const StudyLayout& layout,
                                       const StudyAccumulator& state);

}  // namespace insmc::mc
