#include "tests/fuzz/fuzz_entry.h"

#include "montecarlo/study/aggregate/accumulator_state.h"

#include <boost/program_options.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "apps/config_options.h"
#include "apps/option_sources.h"
#include "apps/study_options.h"
#include "apps/subcommands.h"
#include "apps/sweep.h"
#include "lib/compensation/scheme.h"
#include "lib/common/input_error.h"
#include "lib/imu/imu_samples.h"
#include "lib/records/record_io.h"
#include "lib/truth/effect.h"
#include "lib/units/quantity.h"
#include "montecarlo/study/aggregate/byte_io.h"
#include "montecarlo/study/check/bounds_file.h"
#include "montecarlo/study/run/checkpoint.h"
#include "montecarlo/study/run/run_file.h"

namespace insmc::fuzz {
namespace {

template <class F>
Outcome guarded(F&& f) {
  try {
    f();
    return Outcome::kAccepted;
  } catch (const InputError&) {
    return Outcome::kRefused;
  }
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz: %s\n", what);
  std::abort();
}

/// The input as a sequence of choices; past its end every choice is 0.
class Choices {
 public:
  explicit Choices(std::string_view data) : data_(data) {}
  unsigned byte() { return at_ < data_.size() ? static_cast<unsigned char>(data_[at_++]) : 0u; }
  unsigned u16() { return byte() | byte() << 8; }
  /// A value with one of `units`, as a user types it: up to 65535 with 0
  /// to 3 decimals ("4608ms", "4.608s", "15min").
  template <std::size_t N>
  std::string quantity(const std::array<const char*, N>& units) {
    const unsigned value = u16(), form = byte();
    const int decimals = static_cast<int>(form % 4);
    return fmt::format("{:.{}f}{}", value / std::pow(10.0, decimals), decimals, units[(form / 4) % N]);
  }
  std::string_view rest() const { return data_.substr(std::min(at_, data_.size())); }

 private:
  std::string_view data_;
  std::size_t at_ = 0;
};

constexpr std::array<const char*, 4> kTimeUnits = {"s", "ms", "min", "h"};

/// The SI value of `text`, NaN when the command will refuse it anyway.
double si_or_nan(const std::string& text, Dimension d) {
  try {
    return parse_quantity(text, d, "fuzz");
  } catch (const InputError&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

/// A folder of this process for the files the commands read and write
/// (in memory where /dev/shm is; under INSMC_FUZZ_SCRATCH when set, which
/// scripts/fuzz.sh removes whichever way the fuzzer exits), removed when
/// the process exits normally: its files are megabytes of that memory.
class ScratchFolder {
 public:
  ScratchFolder() {
    const char* chosen = std::getenv("INSMC_FUZZ_SCRATCH");
    const std::filesystem::path base = chosen != nullptr && *chosen != '\0'      ? chosen
                                       : std::filesystem::is_directory("/dev/shm") ? "/dev/shm"
                                                                                  : "/tmp";
    path_ = base / fmt::format("insmc-fuzz-{}", ::getpid());
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

const std::filesystem::path& scratch() {
  static const ScratchFolder folder;
  return folder.path();
}

/// Runs a subcommand as insmc's main does (InputError and Boost's parse
/// errors are its exit 2); a record file it wrote must be read back.
Outcome run_writing_records(int (*command)(const app::Args&), const app::Args& args,
                            const std::filesystem::path& out) {
  std::filesystem::remove(out);
  const Outcome outcome = guarded([&] {
    try {
      command(args);
    } catch (const boost::program_options::error& e) {
      throw InputError(app::parse_error_message(e));
    }
  });
  if (outcome == Outcome::kAccepted) {
    try {
      read_record_file(out);
    } catch (const InputError& e) {
      std::fprintf(stderr, "fuzz: %s\n", e.what());
      fail("a record file written is refused by its reader");
    }
  }
  return outcome;
}

}  // namespace

Outcome records(std::string_view data) {
  return guarded([&] {
    const RecordFile file = parse_record_text(data, "fuzz.csv");
    const std::string text = write_record_file(file);  // asserts the file is valid
    if (!(parse_record_text(text, "rewritten.csv") == file)) fail("record file changed on write and read");
  });
}

Outcome imu(std::string_view data) {
  if (data.empty()) return Outcome::kRefused;
  const auto choice = static_cast<unsigned char>(data[0]);
  data.remove_prefix(1);
  ImuCsvOptions o;
  o.gyro_unit = std::array{GyroUnit::kDegPerS, GyroUnit::kRadPerS, GyroUnit::kDegPerH}[choice % 3];
  o.accel_unit = (choice / 3) % 2 == 0 ? AccelUnit::kG : AccelUnit::kMps2;
  if ((choice / 6) % 2 == 0) {
    o.rate_hz = std::array{100.0, 1.0, 1e5, 7.5}[(choice / 12) % 4];
  } else {
    o.time_column = "t";
    o.time_unit_s = std::array{1.0, 1e-3, 60.0, 3600.0}[(choice / 12) % 4];
  }
  if (choice >= 48 * 4) {  // short names, so the fuzzer finds a header soon
    o.gyro_columns = {"a", "b", "c"};
    o.accel_columns = {"x", "y", "z"};
  }
  return guarded([&] { parse_imu_csv(data, "fuzz.csv", o); });
}

Outcome bounds(std::string_view data) {
  return guarded([&] { mc::parse_bounds_text(data, "fuzz.txt"); });
}

Outcome config(std::string_view data) {
  namespace po = boost::program_options;
  po::options_description options("Options");
  options.add_options()("samples", po::value<std::uint64_t>()->default_value(100000))(
      "seed", po::value<std::uint64_t>())("threads", po::value<int>())("leveling-gain", po::value<double>())(
      "latitude", po::value<std::string>()->default_value("45deg"))(
      "bound", po::value<std::vector<std::string>>()->composing())("dist", po::value<std::vector<std::string>>())(
      "quick", po::bool_switch())("study.alpha", po::value<double>())("help,h", "")(
      "config", po::value<std::string>());
  return guarded([&] {
    po::variables_map vm;
    po::store(app::parse_config_text(data, "fuzz.ini", options), vm);
    po::notify(vm);
  });
}

Outcome checkpoint(std::string_view data) {
  if (data.empty()) return Outcome::kRefused;
  std::string bytes;
  if (static_cast<unsigned char>(data[0]) % 2 == 1) {
    bytes = "insmc checkpoint\n";
    bytes.append(data.substr(1));
    mc::byte_io::put_u64(bytes, mc::fnv1a64(bytes));
  } else {
    bytes = std::string(data.substr(1));
  }
  return guarded([&] {
    const mc::Checkpoint ck = mc::decode_checkpoint(bytes, "fuzz.ck");
    // The state as run --resume reads it; one it accepts is written back the same.
    try {
      // Read, written and read again: the second writing is the first.
      const mc::AccumulatorState state = mc::deserialize_state(ck.state);
      const std::string once = mc::serialize_state(state.outputs, state.kept);
      const mc::AccumulatorState again = mc::deserialize_state(once);
      if (mc::serialize_state(again.outputs, again.kept) != once) fail("checkpoint state differs after a round trip");
    } catch (const std::runtime_error&) {
      throw InputError("fuzz.ck", "state", "corrupt");  // what run --resume says of it
    }
  });
}

Outcome run_json(std::string_view data) {
  namespace po = boost::program_options;
  po::options_description opts("Options");
  opts.add(app::study_options_description(true));
  return guarded([&] {
    // Each element an option by name through the one check of files of
    // options (apps/option_sources.h), then stored as run --from stores it.
    const po::parsed_options kept = app::run_file_options(mc::run_arguments_from_json(data, "fuzz.json"), opts,
                                                          "--from", "fuzz.json", "settings.arguments");
    try {
      po::variables_map vm;
      po::store(kept, vm);
      po::notify(vm);
    } catch (const po::error& e) {
      throw InputError(app::parse_error_message(e));  // main's one line, exit 2
    }
  });
}

Outcome options(std::string_view data) {
  app::Args args;
  constexpr std::size_t kMaxTokens = 64;
  while (!data.empty() && args.size() < kMaxTokens) {
    const std::size_t nl = data.find('\n');
    std::string token(data.substr(0, nl));
    data = nl == std::string_view::npos ? std::string_view() : data.substr(nl + 1);
    if (token.find("config") != std::string::npos) continue;  // would read a file
    args.push_back(std::move(token));
  }
  namespace po = boost::program_options;
  po::options_description opts("Options");
  opts.add(app::study_options_description(true));
  return guarded([&] {
    try {
      const auto vm = app::parse_args(args, "run", "", opts, app::Lists::kSweeps);
      if (!vm) return;
      const mc::StudyConfig config = app::read_study_config(*vm, true);
      mc::check_sweep_points(config, app::find_sweeps(*vm));
    } catch (const po::error& e) {
      throw InputError(app::parse_error_message(e));  // main's one line, exit 2
    }
  });
}

Outcome quantity(std::string_view data) {
  if (data.empty()) return Outcome::kRefused;
  const auto choice = static_cast<unsigned char>(data[0]) % 8;
  data.remove_prefix(1);
  return guarded([&] {
    if (choice == 7) {
      parse_rate_hz(data, "--rate");
      return;
    }
    const auto d = static_cast<Dimension>(choice);
    const double v = parse_quantity(data, d, "--x");
    parse_quantity(format_quantity(v, d), d, "--x");  // what run.json and the INI round trip write
  });
}

Outcome import_imu(std::string_view data) {
  Choices in(data);
  const unsigned form = in.byte();
  constexpr std::array<double, 8> kRatesHz = {1, 2, 5, 10, 20, 50, 100, 3.7};
  const double rate_hz = kRatesHz[form % 8];
  const bool timed = form & 8, split = form & 16, keep_bias = form & 32, noise = form & 64, ms_clock = form & 128;
  // Up to 196,607 samples: 48 h at 1 Hz and more. With the raw-noise stage
  // on, at most 3,000 an input: its fit on a recording no model fits (any
  // periodic byte pattern) tries every shorter range of levels, minutes under
  // the fuzzer's instrumentation at 60,000 samples; its cost beyond is the
  // noise stage's own, measured in its tests.
  const std::size_t drawn_samples = 2 + 3 * std::size_t{in.u16()};
  const std::size_t samples = noise ? std::min<std::size_t>(drawn_samples, 3'000) : drawn_samples;
  const std::string align = in.quantity(kTimeUnits), test = in.quantity(kTimeUnits), nav = in.quantity(kTimeUnits),
                    interval = in.quantity(kTimeUnits);
  const int latitude_deg = static_cast<signed char>(in.byte());
  // Milliseconds an input: the output rows of all runs within 2e5.
  const double run_s = si_or_nan(test, Dimension::kTime) + si_or_nan(nav, Dimension::kTime);
  const double runs = split ? std::max(1.0, samples / rate_hz / (run_s + si_or_nan(align, Dimension::kTime))) : 1.0;
  if (runs * run_s / si_or_nan(interval, Dimension::kTime) > 2e5) return Outcome::kRefused;

  // A still sensor at the latitude (x north), with the rest of the input as noise.
  const std::string_view noise_bytes = in.rest();
  const auto wiggle = [&](std::size_t k, int channel) {
    if (noise_bytes.empty()) return 0.0;
    return (static_cast<unsigned char>(noise_bytes[(7 * k + channel) % noise_bytes.size()]) - 128.0) * 1e-7;
  };
  const double w_dps = 15.041 / 3600, lat = latitude_deg * 3.141592653589793 / 180;
  const std::filesystem::path csv = scratch() / "imu.csv", out = scratch() / "imu.rec";
  {
    std::ofstream file(csv);
    file << (timed ? "t," : "") << "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
    for (std::size_t k = 0; k < samples; ++k) {
      if (timed) file << fmt::format("{},", static_cast<double>(k) / rate_hz * (ms_clock ? 1e3 : 1.0));
      file << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", w_dps * std::cos(lat) + wiggle(k, 0),
                          wiggle(k, 1), -w_dps * std::sin(lat) + wiggle(k, 2), 10 * wiggle(k, 3), 10 * wiggle(k, 4),
                          -1 + 10 * wiggle(k, 5));
    }
  }
  app::Args args = {"--input",          csv.string(),   "--out",           out.string(),
                    "--latitude",       fmt::format("{}deg", latitude_deg),
                    "--align-duration", align,          "--test-duration", test,
                    "--nav-duration",   nav,            "--interval",      interval,
                    "--runs-from",      split ? "split" : "file",
                    "--gyro-bias",      keep_bias ? "keep" : "remove",
                    "--noise",          noise ? "on" : "off"};
  if (timed) {
    for (const char* a : {"--time-column", "t", "--time-unit", ms_clock ? "ms" : "s"}) args.emplace_back(a);
  } else {
    args.insert(args.end(), {"--rate", fmt::format("{}Hz", rate_hz)});
  }
  return run_writing_records(app::cmd_import_imu, args, out);
}

Outcome simulate(std::string_view data) {
  Choices in(data);
  const unsigned form = in.byte();
  const int runs = 1 + static_cast<int>(form % 2);
  const bool system2 = form & 2, foreign = (form / 4) % 4 == 0, realign = form & 16;
  const std::vector<Scheme> schemes = all_schemes();
  const Scheme scheme = schemes[in.byte() % schemes.size()];
  const std::string test = in.quantity(kTimeUnits), tau = in.quantity(kTimeUnits), nav = in.quantity(kTimeUnits),
                    step = in.quantity(kTimeUnits);
  const int latitude_deg = static_cast<signed char>(in.byte());
  const std::string dv_pulse = in.quantity(std::array<const char*, 3>{"mps", "ftps", "mmps"});
  const std::string resolution = in.quantity(std::array<const char*, 3>{"m", "ft", "km"});
  const std::string realignment = in.quantity(kTimeUnits);
  // Milliseconds an input: ~2e4 rows and integration steps a run, and at
  // most 1800 test-run intervals (a study's cap) for the scheme's estimators;
  // the cost of more is the budgets' (docs/robustness.md), not this target's.
  const double test_s = si_or_nan(test, Dimension::kTime), tau_s = si_or_nan(tau, Dimension::kTime);
  const double span_s = test_s + si_or_nan(nav, Dimension::kTime) +
                        (realign ? si_or_nan(realignment, Dimension::kTime) : 0.0);
  if (span_s / tau_s > 2e4 || span_s / si_or_nan(step, Dimension::kTime) > 2e4 || test_s / tau_s > 1800)
    return Outcome::kRefused;

  const std::filesystem::path out = scratch() / "simulate.rec";
  app::Args args = {"--out",           out.string(),  "--runs",         std::to_string(runs),
                    "--seed",          std::to_string(in.u16()),
                    "--system",        system2 ? "2" : "1",
                    "--scheme",        std::string(to_string(scheme)),
                    "--layout",        foreign ? "foreign" : "own",
                    "--test-duration", test,          "--filter-interval", tau,
                    "--nav-duration",  nav,           "--step",           step,
                    "--latitude",      fmt::format("{}deg", latitude_deg),
                    "--dv-pulse",      dv_pulse,      "--position-resolution", resolution};
  if (realign) args.insert(args.end(), {"--realignment-duration", realignment});
  // Up to two effects, each parameter at its default times a factor (0, a
  // half, 1, 2, 10, 1000 or -1).
  const std::span<const EffectInfo> effects = effect_registry();
  constexpr std::array<double, 7> kFactors = {0, 0.5, 1, 2, 10, 1e3, -1};
  for (unsigned e = in.byte() % 3; e > 0; --e) {
    const EffectInfo& info = effects[in.byte() % effects.size()];
    std::string text(info.name);
    for (std::size_t p = 0; p < info.parameters.size(); ++p) {
      const EffectParameter& parameter = info.parameters[p];
      text += fmt::format("{}{}={}", p == 0 ? ":" : ",", parameter.name,
                          format_quantity(parameter.default_si * kFactors[in.byte() % kFactors.size()],
                                          parameter.dimension));
    }
    args.insert(args.end(), {"--effect", text});
  }
  return run_writing_records(app::cmd_simulate, args, out);
}

}  // namespace insmc::fuzz
