#pragma once
/// The IEEE Std 952-1997 Annex C readings of an Allan deviation curve, the
/// engineer's cross-check beside the fitted model (docs/noise.md §3):
/// - white rate N (ARW / VRW): the −½ line σ = N/√τ (C.12) through the
///   levels on the −½ slope, read at τ = 1 s;
/// - bias instability B: the floor, B = min σ / √(2 ln 2/π) = min σ / 0.664
///   (C.15);
/// - rate random walk K: the +½ line σ = K√(τ/3) (C.18) through the levels
///   on the +½ slope beyond the floor, read at τ = 3 s; only where such a
///   slope exists.
/// A slope "exists" over a stretch of consecutive octave levels whose local
/// slopes ln(σ_{j+1}/σ_j)/ln 2 all lie within ±¼ of the slope (halfway to
/// the neighbouring power laws, 0 and ±1). For the +½ slope the rise must
/// also be larger than the levels' own scatter: the last level's lower
/// bound above the floor level's upper bound.
#include <span>

#include "lib/noise/allan_variance.h"

namespace insmc::noise {

struct SlopeReading {
  bool found = false;
  double value_si = 0;
  double tau_from_s = 0, tau_to_s = 0;  ///< the levels the reading uses
};

struct SlopeReadings {
  SlopeReading white;        ///< N: the −½ line at τ = 1 s
  SlopeReading instability;  ///< B: the floor / 0.664 (tau_from_s = tau_to_s = the floor's τ)
  SlopeReading walk;         ///< K: the +½ line at τ = 3 s
};

/// The readings of the rows (octave-spaced, increasing τ, adev > 0 where
/// the channel has noise). Nothing is found on fewer than two levels.
SlopeReadings read_slopes(std::span<const AllanRow> rows);

}  // namespace insmc::noise
