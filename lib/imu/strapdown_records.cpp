#include "lib/imu/strapdown_records.h"

#include <cmath>

namespace insmc {

RecordRun record_run_of(const StrapdownRun& r, double test_duration_s, std::int64_t id) {
  RecordRun out;
  out.id = id;
  out.rows.reserve(r.t_s.size());
  for (std::size_t k = 0; k < r.t_s.size(); ++k) {
    RecordRow row;
    row.run = id;
    row.t_s = r.t_s[k];
    row.phase = r.t_s[k] <= test_duration_s ? Phase::kTest : Phase::kNav;  // (docs/records.md: test for 0 ≤ t ≤ T)
    for (int c = 0; c < 3; ++c)
      if (std::isfinite(r.accel_error_ap_mps2[k][c])) row.f_mps2[c] = r.accel_error_ap_mps2[k][c];
    row.r_ap_m = r.position_error_ap_m[k];
    out.rows.push_back(row);
  }
  return out;
}

}  // namespace insmc
