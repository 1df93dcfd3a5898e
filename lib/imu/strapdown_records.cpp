#include "lib/imu/strapdown_records.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lib/common/assert.h"
#include "lib/common/input_text.h"
#include "lib/records/import_keys.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

std::string join_columns(const std::array<std::string, 3>& c) { return fmt::format("{},{},{}", c[0], c[1], c[2]); }

}  // namespace

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

int runs_from_input(const ImuSamples& samples, const StrapdownOptions& nav, RunsFrom runs_from) {
  return runs_from == RunsFrom::kFile ? 1 : std::max(1, runs_available(samples, nav));
}

RecordFile imported_file_header(const StrapdownOptions& nav, const ImuCsvOptions& csv, RunsFrom runs_from) {
  RecordFile file;
  file.header = RecordHeader::make(nav.latitude_rad / kDegToRad, System::kTheodolite, nav.test_duration_s, Scheme::kNone);
  file.header.set(kKeyDvPulseMps, 0.0);  // continuous accelerometer output
  file.header.set(kKeyPositionResolutionM, 0.0);
  file.header.set("filter_interval_s", nav.output_interval_s);
  // Informational (imu.*): how the records were made.
  file.header.set(import_keys::kGyroUnit, std::string(to_string(csv.gyro_unit)));
  file.header.set(import_keys::kAccelUnit, std::string(to_string(csv.accel_unit)));
  file.header.set(import_keys::kGyroColumns, join_columns(csv.gyro_columns));
  file.header.set(import_keys::kAccelColumns, join_columns(csv.accel_columns));
  if (csv.time_column.empty())
    file.header.set(import_keys::kRateHz, csv.rate_hz);
  else
    file.header.set(import_keys::kTimeColumn, csv.time_column);
  file.header.set(import_keys::kAltitudeM, nav.altitude_m);
  file.header.set(import_keys::kAzimuthDeg, nav.azimuth_rad / kDegToRad);
  file.header.set(import_keys::kAlignDurationS, nav.align_duration_s);
  file.header.set(import_keys::kNavDurationS, nav.nav_duration_s);
  file.header.set(import_keys::kGyroBias, std::string(to_string(nav.gyro_bias)));
  file.header.set(import_keys::kRunsFrom, std::string(runs_from == RunsFrom::kFile ? "file" : "split"));
  file.header.set(import_keys::kSiteGravityMps2, stationary_site(nav).gravity_mps2);
  return file;
}

void append_imported_runs(RecordFile& file, const std::vector<ImuSamples>& inputs,
                          const std::vector<std::string>& sources, const StrapdownOptions& nav, RunsFrom runs_from) {
  INSMC_ASSERT(sources.size() == inputs.size(), "{} sources for {} inputs", sources.size(), inputs.size());
  std::int64_t run_id = 0;
  for (std::size_t input = 0; input < inputs.size(); ++input) {
    const ImuSamples& samples = inputs[input];
    const int runs = runs_from_input(samples, nav, runs_from);
    for (int j = 0; j < runs; ++j, ++run_id) {
      const StrapdownRun r = run_strapdown(samples, j * nav.run_duration_s(), nav);
      const auto key = [run_id](std::string_view what) { return import_keys::run_key(run_id, what); };
      file.header.set(key("source"), one_line_value(sources[input]));  // escaped: a path may hold any byte
      file.header.set(key("switch_time_s"), r.switch_time_s);
      const StrapdownAlignment& a = r.alignment;
      for (int k = 0; k < 3; ++k)
        file.header.set(key(fmt::format("gyro_bias_{}_radps", "xyz"[k])), a.gyro_bias_b_radps[k]);
      file.header.set(key("accel_magnitude_mps2"), a.mean_accel_b_mps2.norm());
      file.header.set(key(import_keys::kRunRollDeg), a.roll_rad / kDegToRad);
      file.header.set(key(import_keys::kRunPitchDeg), a.pitch_rad / kDegToRad);
      file.runs.push_back(record_run_of(r, nav.test_duration_s, run_id));
    }
  }
}

}  // namespace insmc
