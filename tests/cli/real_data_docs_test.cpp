// The command block of docs/real-data/README.md runs as pasted: extracted
// from the document, its data folder and program path replaced by a
// synthetic file of the same layout (six 1 s-mean recordings, the columns
// of the ADIS16405 set) and the built insmc, run with `bash -e`.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <sstream>

#include "tests/cli/run_program.h"
#include "tests/ordered_draws.h"

namespace insmc::testing {
namespace {

std::string documented_block() {
  const char* src = std::getenv("INSMC_SOURCE_DIR");
  if (!src) return {};
  const std::string doc = read_file(std::filesystem::path(src) / "docs" / "real-data" / "README.md");
  const std::size_t data = doc.find("\nDATA=");
  if (data == std::string::npos) return {};
  const std::size_t open = doc.rfind("```sh\n", data), close = doc.find("\n```", data);
  return doc.substr(open + 6, close - open - 6);
}

TEST(RealDataDocs, TheCommandBlockRunsAsPasted) {
  const std::string block = documented_block();
  ASSERT_FALSE(block.empty()) << "no ```sh block with DATA= in docs/real-data/README.md";
  TempDir dir;
  const auto data = dir.path() / "data", work = dir.path() / "work";
  std::filesystem::create_directories(data);
  {
    std::ofstream f(data / "adis16405_runs1-6_1hz_means.csv");
    f << "run,t_mid_s,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
    std::mt19937_64 rng(21);
    std::normal_distribution<double> e(0.0, 1.0);
    for (int run = 1; run <= 6; ++run)
      for (int k = 0; k < 6700; ++k) {
        const auto z = ordered_draws<6>(e, rng);
        f << fmt::format("{},{:.3f},{:.6f},{:.6f},{:.6f},{:.7f},{:.7f},{:.7f}\n", run, k + 0.495, 0.4 + 0.04 * z[0],
                         -0.4 + 0.04 * z[1], -0.3 + 0.04 * z[2], -0.004 + 4e-4 * z[3], -0.002 + 4e-4 * z[4],
                         -1.0 + 4e-4 * z[5]);
      }
  }
  std::istringstream lines(block);
  std::string script = "set -e -o pipefail\n", line;
  while (std::getline(lines, line)) {
    if (line.rfind("DATA=", 0) == 0) line = "DATA='" + data.string() + "'";
    if (line.rfind("INSMC=", 0) == 0) line = "INSMC='" + insmc_path() + "'";
    for (std::size_t p = line.find("/tmp/adis"); p != std::string::npos; p = line.find("/tmp/adis"))
      line.replace(p, 9, work.string());
    script += line + "\n";
  }
  const auto script_path = dir.path() / "block.sh";
  std::ofstream(script_path) << script;
  const ProgramResult r = run_shell(fmt::format("cd '{}' && bash '{}'", std::getenv("INSMC_SOURCE_DIR"), script_path.string()));
  ASSERT_EQ(r.exit_code, 0) << script << "\n" << r.err;
  for (const char* out : {"noise_adis6/noise.md", "adis6.csv", "gap_adis6/gap.json", "adis18.csv", "gap_adis18/gap.json"})
    EXPECT_TRUE(std::filesystem::exists(work / out)) << out;
  // The report's first sentence is what an engineer needs first about this
  // MEMS unit: how far outside Table 3.1 it lies, per sensor.
  const std::string md = read_file(work / "gap_adis6" / "gap.md");
  const std::string first = md.substr(0, md.find("\n\n", md.find("\n\n") + 2));
  EXPECT_NE(first.find("The unit lies outside the model's priors"), std::string::npos) << first;
}

}  // namespace
}  // namespace insmc::testing
