// sensitivity.csv (covariance): the map of the uncompensated outputs on the
// uncertainties, checked against the two other ways insmc states them: a
// replayed sample's errors (the engine's values for that sample's x) and the
// exact covariance (each uniform parameter's variance b²/3 through the map).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/csv_rows.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

struct Map {
  std::vector<std::string> names;                          // the parameters, in the file's column order
  std::map<std::string, std::vector<double>> coefficients;  // "system,t_min,component" -> row
};

Map read_map(const std::string& text) {
  const auto rows = csv_rows(text);
  Map m;
  m.names.assign(rows.at(0).begin() + 4, rows.at(0).end());
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::vector<double> c;
    for (std::size_t k = 4; k < rows[i].size(); ++k) c.push_back(std::stod(rows[i][k]));
    m.coefficients[rows[i][1] + "," + rows[i][2] + "," + rows[i][3]] = c;
  }
  return m;
}

/// The cells of a CSV line with quoted cells ("1,2").
std::vector<std::string> quoted_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (char ch : line) {
    if (ch == '"') quoted = !quoted;
    else if (ch == ',' && !quoted) cells.emplace_back();
    else cells.back() += ch;
  }
  return cells;
}

/// The section of `text` after the line `header`, up to the next blank line.
std::string section(const std::string& text, const std::string& header) {
  const std::size_t at = text.find(header + "\n");
  if (at == std::string::npos) return "";
  const std::size_t end = text.find("\n\n", at);
  return text.substr(at, end == std::string::npos ? std::string::npos : end - at + 1);
}

TEST(Sensitivity, TheMapTimesAReplayedSamplesUncertaintiesGivesItsErrors) {
  TempDir dir;
  const auto cov = run_insmc("covariance --fidelity paper --scheme none --quiet --out " + dir.str());
  ASSERT_EQ(cov.exit_code, 0) << cov.err;
  const Map m = read_map(read_file(dir.path() / "sensitivity.csv"));
  ASSERT_EQ(m.coefficients.size(), 2u * 3u * 5u);  // systems × report times × (x, y, z, north, east)
  const auto replay = run_insmc("run --fidelity paper --scheme none --samples 100 --replay 42");
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  std::map<std::string, double> x;
  for (const auto& row : csv_rows(section(replay.out, "uncertainty,value_si")))
    if (row.size() == 2 && row[0] != "uncertainty") x[row[0]] = std::stod(row[1]);
  ASSERT_EQ(x.size(), m.names.size());
  int checked = 0;
  for (const auto& row : csv_rows(section(replay.out, "scheme,system,clock,axis,t_min,error_m"))) {
    if (row.size() != 6 || row[0] != "none") continue;
    const auto value = [&](const std::string& component, double& magnitude) {
      const std::vector<double>& c = m.coefficients.at(row[1] + "," + row[4] + "," + component);
      double sum = 0;
      for (std::size_t k = 0; k < c.size(); ++k) {
        sum += c[k] * x.at(m.names[k]);
        magnitude += std::abs(c[k] * x.at(m.names[k]));
      }
      return sum;
    };
    double magnitude = 0;
    const double want = row[3] == "horizontal" ? std::hypot(value("north", magnitude), value("east", magnitude))
                                               : value(row[3], magnitude);
    // Both files print 9 significant digits: each product is off by at most
    // 1e-8 of itself, the printed error by 5e-9 of itself.
    EXPECT_NEAR(std::stod(row[5]), want, 1e-8 * magnitude + 5e-9 * std::abs(want)) << row[1] << " " << row[3] << " " << row[4];
    ++checked;
  }
  EXPECT_EQ(checked, 2 * 3 * 4);
}

TEST(Sensitivity, UniformVariancesThroughTheMapGiveTheExactCovariance) {
  TempDir dir;
  const auto cov = run_insmc("covariance --fidelity linear --scheme none,5.4 --quiet --out " + dir.str());
  ASSERT_EQ(cov.exit_code, 0) << cov.err;
  const Map m = read_map(read_file(dir.path() / "sensitivity.csv"));
  const std::string sensitivity = read_file(dir.path() / "sensitivity.csv");
  EXPECT_EQ(sensitivity.find("\n5.4,"), std::string::npos) << "5.4 acts on the test run's data, not on x alone";
  const auto params = run_insmc("params --format csv");
  std::map<std::string, double> variance;  // the default distributions are uniform on [-b, b]
  std::istringstream lines(params.out);
  for (std::string line; std::getline(lines, line);)
    if (const auto row = quoted_cells(line); row.size() > 6 && row[0] != "name") {
      ASSERT_EQ(row[6], "uniform") << row[0];
      variance[row[0]] = std::stod(row[4]) * std::stod(row[4]) / 3;
    }
  int checked = 0;
  for (const auto& row : csv_rows(read_file(dir.path() / "covariance.csv"))) {
    if (row.size() < 5 || row[0] != "none") continue;
    const auto mean_square = [&](const std::string& component) {
      const std::vector<double>& c = m.coefficients.at(row[1] + "," + row[3] + "," + component);
      double sum = 0;
      for (std::size_t k = 0; k < c.size(); ++k) sum += c[k] * c[k] * variance.at(m.names[k]);
      return sum;
    };
    const double rms = std::sqrt(row[2] == "horizontal" ? mean_square("north") + mean_square("east")
                                                        : mean_square(row[2]));
    EXPECT_NEAR(std::stod(row[4]), rms, 2e-8 * rms) << row[1] << " " << row[2] << " " << row[3];
    ++checked;
  }
  EXPECT_EQ(checked, 2 * 3 * 4);
}

}  // namespace
}  // namespace insmc::testing
