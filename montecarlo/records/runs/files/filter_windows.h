#pragma once
/// Short filter windows summed into longer ones. A record's f_k is the
/// velocity increment counted over the window τ ending at t_s, divided by τ
/// (fig. 5.2's filter box); the mean of n consecutive, gap-free windows is
/// therefore exactly what a box of n·τ would have counted. Records written
/// at 10–100 Hz carry tens of thousands of f rows per run, and the gap
/// model's cost grows with the rows: nothing the diagnosis looks for lives
/// above 0.5 Hz (Schuler, earth rate, polynomials, noise densities and
/// pulse counting, which the model keeps at the new τ), so windows shorter
/// than a second are summed into windows of at least a second.
#include "lib/records/record.h"

namespace insmc::runs {

/// What coarsen_filter_windows did.
struct FilterWindows {
  double tau_s = 0.0;  ///< the window of the f rows after it
  int factor = 1;      ///< windows summed into one (1: the record is left as it was)
  long dropped = 0;    ///< f values left out: their block had a gap, a phase change or an off-grid spacing
};

/// Sums the f windows of `file` (length tau_s) in blocks of n consecutive
/// windows, n the smallest integer with n·τ ≥ min_tau_s that divides T/τ
/// when T/τ is whole (so the block ends fall on the test run's grid τ'..T),
/// if one does up to twice the least, else the least;
/// a block is kept, per axis, when it has n values of one phase spaced τ
/// apart, and its mean goes on its last row. Every other f value is
/// cleared. Does nothing when τ ≥ min_tau_s.
FilterWindows coarsen_filter_windows(RecordFile& file, double tau_s, double test_duration_s, double min_tau_s);

}  // namespace insmc::runs
