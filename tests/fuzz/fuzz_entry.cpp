#include "tests/fuzz/fuzz_entry.h"

#include "montecarlo/aggregate/accumulator_state.h"

#include <boost/program_options.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "apps/config_options.h"
#include "apps/option_sources.h"
#include "apps/study_options.h"
#include "apps/sweep.h"
#include "lib/common/input_error.h"
#include "lib/imu/imu_samples.h"
#include "lib/records/record_io.h"
#include "lib/units/quantity.h"
#include "montecarlo/aggregate/byte_io.h"
#include "montecarlo/check/bounds_file.h"
#include "montecarlo/study/checkpoint.h"
#include "montecarlo/study/run_file.h"

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
  return guarded([&] { mc::run_arguments_from_json(data, "fuzz.json"); });
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

}  // namespace insmc::fuzz
