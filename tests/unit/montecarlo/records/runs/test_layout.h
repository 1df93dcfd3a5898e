#pragma once
// The row layout the run-model and diagnosis unit tests share: f rows every
// 10 s and r rows every 60 s on three axes, a test run of T = 900 s, then
// navigation; and a site of 10 s filter windows and 0.1 ft/s pulses.
#include <cmath>

#include "lib/units/units.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::runs::testing {

inline Layout test_layout(double end_s) {
  Layout l;
  for (int stage = 0; stage < 2; ++stage) {
    for (double t = 10.0; t <= end_s + 1e-9; t += 10.0) {
      const bool test = t <= 900.0;
      if (test != (stage == 0)) continue;
      const Stage st = test ? Stage::kTest : Stage::kNav;
      const int w = test ? 0 : nav_window(t, 900.0);
      for (int k = 0; k < 3; ++k) l.rows.push_back({t, Quantity::kF, k, group_of(st, Quantity::kF, k, w)});
      if (std::fmod(t, 60.0) == 0.0)
        for (int k = 0; k < 3; ++k) l.rows.push_back({t, Quantity::kR, k, group_of(st, Quantity::kR, k, w)});
    }
    if (stage == 0) l.test_rows = static_cast<int>(l.rows.size());
  }
  return l;
}

inline RecordSite test_site() {
  RecordSite s;
  s.filter_interval_s = 10.0;
  s.dv_pulse_mps = 0.1 * kFtpsToMps;
  return s;
}

}  // namespace insmc::runs::testing
