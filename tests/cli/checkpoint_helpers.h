#pragma once
// Helpers of the checkpoint and MPI end-to-end tests: byte comparison of
// output folders, a sample count sized to this build's speed, waiting for a
// periodic checkpoint, and reading run.json's resumed_from_sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <thread>

#include "tests/cli/run_program.h"

namespace insmc::testing {

/// The files whose bytes the README promises for the same settings.
inline void expect_same_envelopes(const std::filesystem::path& expected, const std::filesystem::path& actual) {
  for (const char* f : {"envelope.csv", "envelope_grid.csv", "envelope.md", "envelope.gp", "envelope.svg", "envelope.png"}) {
    ASSERT_TRUE(std::filesystem::exists(actual / f)) << actual / f;
    EXPECT_TRUE(read_file(expected / f) == read_file(actual / f)) << f << " differs: " << expected << " " << actual;
  }
}

inline std::string fmt_samples(std::uint64_t samples) { return " --samples " + std::to_string(samples); }

/// Samples that keep `insmc run <study>` busy for about `seconds` in this
/// build (Release or Debug with sanitizers), measured from two short runs;
/// with a partial last block.
inline std::uint64_t samples_for_seconds(const std::string& study, double seconds) {
  const auto time_run = [&](std::uint64_t samples) {
    const auto start = std::chrono::steady_clock::now();
    const ProgramResult r = run_insmc("run" + fmt_samples(samples) + study + " --format csv");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  constexpr std::uint64_t kSmall = 1024, kLarge = 64 * 1024;
  const double per_sample_s = std::max(1e-9, (time_run(kLarge) - time_run(kSmall)) / (kLarge - kSmall));
  const double wanted = seconds / per_sample_s;
  const auto blocks = static_cast<std::uint64_t>(std::clamp(wanted / 1024, 40.0, 20000.0));
  return blocks * 1024 + 7;
}

/// Waits until `checkpoint` has been rewritten after its first version
/// (written before the work starts): the run is then under way, with its
/// signal handlers installed.
inline void wait_for_a_periodic_checkpoint(const std::filesystem::path& checkpoint) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::string first;
  while (std::chrono::steady_clock::now() < deadline) {
    if (std::filesystem::exists(checkpoint)) {
      const std::string now = read_file(checkpoint);
      if (first.empty()) first = now;
      else if (now != first) return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ADD_FAILURE() << "no periodic checkpoint in " << checkpoint << " within 120 s";
}

/// run.json's "resumed_from_sample".
inline std::uint64_t resumed_from_sample(const std::filesystem::path& run_json) {
  const std::string text = read_file(run_json);
  const std::string key = "\"resumed_from_sample\": ";
  const std::size_t at = text.find(key);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no resumed_from_sample in " << run_json;
    return 0;
  }
  return std::stoull(text.substr(at + key.size()));
}

}  // namespace insmc::testing
