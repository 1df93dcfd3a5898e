#include "montecarlo/records/gap/null/import_null.h"

#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

#include "lib/common/assert.h"
#include "lib/records/import_keys.h"
#include "lib/imu/imu_samples.h"
#include "lib/imu/strapdown_records.h"
#include "lib/noise/noise_synthesis.h"
#include "lib/noise/recording.h"
#include "lib/units/units.h"
#include "montecarlo/records/runs/simulation/record_simulation.h"
#include "montecarlo/records/runs/files/raw_stage.h"

namespace insmc::gap {
namespace {

/// The NormalSource streams of the synthesized noise: above every stream the
/// truth effects use (they number theirs from 0), one block per channel.
constexpr std::uint64_t kImportNoiseStream = std::uint64_t{1} << 20;

/// The shortest synthesized sample interval [s]: the null needs the noise as
/// the navigation sees it (filter windows of ≥ 1 s), not the raw rate; the
/// synthesizer turns what is faster into its white-rate limit.
constexpr double kMinSynthesisIntervalS = 0.1;
/// At most this many samples per null run (a 48 h run at 0.86 s) unless the
/// output interval is shorter: the memory and time of one null run stay
/// bounded whatever the header says.
constexpr double kMaxSynthesizedSamples = 2e5;

std::optional<double> number(const RecordHeader& h, std::string_view key) {
  const std::string* v = h.find(key);
  if (!v) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(v->c_str(), &end);
  if (end == v->c_str() || *end != '\0' || !std::isfinite(x)) return std::nullopt;
  return x;
}

/// The largest value a term may give a sample over a run (the IMU reader's
/// caps, lib/imu/imu_samples.h): beyond, the header's value is not a sensor's.
bool within_caps(const noise::NoiseModel& m, noise::SensorKind kind, double dt_s, double run_s) {
  const double cap = kind == noise::SensorKind::kGyro ? kMaxImuGyroRadps : kMaxImuAccelMps2;
  using noise::NoiseTerm;
  const double tc = m.correlation_time_s;
  const double largest[] = {std::sqrt(m[NoiseTerm::kQuantization]) / dt_s, std::sqrt(m[NoiseTerm::kWhiteRate] / dt_s),
                            std::sqrt(m[NoiseTerm::kBiasInstability]), std::sqrt(m[NoiseTerm::kRateRandomWalk] * run_s),
                            std::sqrt(m[NoiseTerm::kRateRamp]) * run_s, std::sqrt(m[NoiseTerm::kGaussMarkov])};
  for (const double x : largest)
    if (!(x <= cap)) return false;
  return m[NoiseTerm::kGaussMarkov] == 0 || (tc > 0 && tc <= kMaxImuDurationS);
}

/// Whether t is one of the import's output times τ, 2τ, …, T + nav.
bool on_output_grid(double t_s, const StrapdownOptions& nav) {
  const long k = std::lround(t_s / nav.output_interval_s);
  return k >= 1 && static_cast<double>(k) * nav.output_interval_s <= nav.test_duration_s + nav.nav_duration_s + 1e-6 &&
         std::abs(static_cast<double>(k) * nav.output_interval_s - t_s) <= 1e-6 * std::max(1.0, t_s);
}

}  // namespace

std::optional<ImportNull> import_null_for(const RecordFile& file, std::vector<std::string>& statements) {
  const RecordHeader& header = file.header;
  const std::optional<runs::RawStage> raw = runs::raw_stage_from_header(header);
  if (!raw) return std::nullopt;
  ImportNull in;
  StrapdownOptions& nav = in.nav;
  const auto need = [&](std::string_view key) {
    const std::optional<double> v = number(header, key);
    if (!v) statements.push_back(fmt::format("the null does not go through the import: the header has no usable {}", key));
    return v;
  };
  const auto align = need(import_keys::kAlignDurationS), nav_s = need(import_keys::kNavDurationS),
             interval = need(kKeyFilterIntervalS);
  if (!align || !nav_s || !interval) return std::nullopt;
  nav.latitude_rad = header.latitude_deg() * kDegToRad;
  nav.altitude_m = number(header, import_keys::kAltitudeM).value_or(0.0);
  nav.azimuth_rad = number(header, import_keys::kAzimuthDeg).value_or(0.0) * kDegToRad;
  nav.align_duration_s = *align;
  nav.test_duration_s = header.test_duration_s();
  nav.nav_duration_s = *nav_s;
  nav.output_interval_s = *interval;
  const std::string* mode = header.find(import_keys::kGyroBias);
  nav.gyro_bias = mode && *mode == "keep" ? GyroBiasMode::kKeep : GyroBiasMode::kRemove;
  std::optional<InputError> e;
  try {
    validate(nav);
  } catch (const InputError& problem) {
    e = problem;
  }
  if (e || nav.run_duration_s() > kMaxRunDurationS + nav.align_duration_s) {
    statements.push_back(fmt::format("the null does not go through the import: its imu.* settings are not an "
                                     "import's ({})", e ? e->what() : "a run longer than 48 h"));
    return std::nullopt;
  }
  // The raw sample interval, coarsened to what the navigation resolves, and
  // a whole fraction of the output interval so the rows fall on samples.
  const double raw_dt = number(header, import_keys::kNoiseSampleIntervalS)
                            .value_or(1.0 / number(header, import_keys::kRateHz).value_or(1.0 / kMinSynthesisIntervalS));
  const double shortest = std::max(kMinSynthesisIntervalS, nav.run_duration_s() / kMaxSynthesizedSamples);
  const double per_interval = std::floor(nav.output_interval_s / std::max(raw_dt, shortest));
  in.sample_interval_s = nav.output_interval_s / std::max(1.0, per_interval);
  for (const runs::RawChannel& ch : raw->channels) {
    std::size_t c = 0;
    while (c < noise::kChannels && noise::channel_name(c) != ch.channel) ++c;
    INSMC_ASSERT(c < noise::kChannels, "raw channel {}", ch.channel);
    if (!within_caps(ch.model, noise::channel_kind(c), in.sample_interval_s, nav.run_duration_s())) {
      statements.push_back(fmt::format("the null does not go through the import: the fitted noise of {} in the "
                                       "header (imu.noise.{}.*) is beyond any sensor's",
                                       ch.channel, ch.channel));
      return std::nullopt;
    }
    in.channels[c] = ch.model;
  }
  for (const RecordRun& r : file.runs)
    for (const RecordRow& row : r.rows)
      if (!on_output_grid(row.t_s, nav)) {
        statements.push_back(fmt::format("the null does not go through the import: run {} has a row at t = {} s, "
                                         "not one of the import's output times (every {} s up to {} s)",
                                         r.id, row.t_s, nav.output_interval_s,
                                         nav.test_duration_s + nav.nav_duration_s));
        return std::nullopt;
      }
  in.description = fmt::format(
      "the null goes through the import: each null run also carries the raw stage's fitted noise, synthesized "
      "every {:.3g} s and imported as the records were (leveling and gyro-bias estimate over {:.4g} s, strapdown)",
      in.sample_interval_s, nav.align_duration_s);
  return in;
}

void add_import_noise(RecordRun& null_run, const RecordHeader& header, std::int64_t pattern_id,
                      const ImportNull& import, std::uint64_t seed, std::uint64_t run) {
  const double roll = number(header, import_keys::run_key(pattern_id, import_keys::kRunRollDeg)).value_or(0.0) * kDegToRad;
  const double pitch =
      number(header, import_keys::run_key(pattern_id, import_keys::kRunPitchDeg)).value_or(0.0) * kDegToRad;
  // The exact outputs of a sensor fixed to the model earth, turned as the run's was.
  const StationarySite site = stationary_site(import.nav);
  const Mat3 C_b_n = C_n_b_from_euler(roll, pitch, import.nav.azimuth_rad).transpose();
  const Vec3 gyro = C_b_n * site.earth_rate_n_radps, accel = C_b_n * site.specific_force_n_mps2;

  const double dt = import.sample_interval_s;
  const auto n = static_cast<std::size_t>(std::ceil(import.nav.run_duration_s() / dt)) + 2;
  const NormalSource normals = runs::philox_normals(seed, run);
  std::vector<noise::NoiseSynthesizer> channels;
  channels.reserve(noise::kChannels);
  for (std::size_t c = 0; c < noise::kChannels; ++c)
    channels.emplace_back(import.channels[c], dt, normals,
                          kImportNoiseStream + c * noise::NoiseSynthesizer::streams_used());
  ImuSamples s;
  s.source = "null through the import";
  s.t_s.resize(n);
  s.gyro_b_radps.resize(n);
  s.accel_b_mps2.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    s.t_s[k] = static_cast<double>(k) * dt;
    for (int i = 0; i < 3; ++i) {
      s.gyro_b_radps[k][i] = gyro[i] + channels[static_cast<std::size_t>(i)].next();
      s.accel_b_mps2[k][i] = accel[i] + channels[static_cast<std::size_t>(3 + i)].next();
    }
  }
  const RecordRun imported = record_run_of(run_strapdown(s, 0.0, import.nav), import.nav.test_duration_s, 0);
  // Row by row on the output grid τ, 2τ, …
  const double tau = import.nav.output_interval_s;
  for (RecordRow& row : null_run.rows) {
    const long k = std::lround(row.t_s / tau) - 1;
    INSMC_ASSERT(k >= 0 && static_cast<std::size_t>(k) < imported.rows.size() &&
                     std::abs(imported.rows[static_cast<std::size_t>(k)].t_s - row.t_s) <= 1e-6 * std::max(1.0, row.t_s),
                 "null row at {} s is not an output time of the import", row.t_s);
    const RecordRow& add = imported.rows[static_cast<std::size_t>(k)];
    if (row.r_ap_m && add.r_ap_m) *row.r_ap_m += *add.r_ap_m;
    for (int c = 0; c < 3; ++c)
      if (row.f_mps2[c] && add.f_mps2[c]) *row.f_mps2[c] += *add.f_mps2[c];
  }
}

}  // namespace insmc::gap
