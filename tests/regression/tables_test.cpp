// Regression of the reproduced tables (tables/generate.h) against the
// report's printed values (tables/data/*.csv, as transcribed) and against
// insmc's own golden values (tests/regression/golden/tables_<convention>.csv).
//
//  * every printed cell is transcribed (the table shapes are counted here from
//    the report, independently of the CSVs) and computed;
//  * every cell more than kNoteThresholdPct off its printed value carries a
//    note, and every note's checkable claim holds (tables/notes/cell_notes.csv);
//  * the computed values equal the golden ones to kGoldenRelTol;
//  * agreement in significant digits (LRE, as Ceres' examples/nist.cc) is
//    reported per table.
// INSMC_UPDATE_GOLDEN=1 rewrites the goldens (OpenMC's --update); review the diff.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <map>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "tables/generate.h"
#include "tables/printed.h"
#include "tables/score.h"

namespace insmc::tables {

/// Test names and failure messages print the convention by name.
void PrintTo(TableConvention c, std::ostream* os) { *os << to_string(c); }

namespace {

/// Printed cells per table, counted from paper/johansen-1969-RE-59.md (rows ×
/// value columns), independently of tables/data/*.csv.
const std::map<std::string, int> kPrintedCellsPerTable = {
    {"3.1", 18},  // 12 bounds, 5 alternative units (0.01 %, 3.44 min, 20 sec, 1 ft/sec, 20 sec), L_0 = 45°
    {"4.1", 48},  // 12 rows × 4 test durations
    {"4.2", 52},  // 13 rows × 4
    {"4.3", 12},  // 3 coefficients × 4 durations
    {"4.3b", 6},  // the drift thresholds after Table 4.3: 2 rows × 3 durations
    {"5.1", 24},  // 8 rows × 3 times
    {"5.2", 30},  // 10 rows × 3 times
};

/// Figure 3.2: the (3.29) terms δV(0), U2, U3, U4, U5 on 0, 5, …, 90 min.
constexpr int kFigureRows = 5;
constexpr int kFigureColumns = 19;

/// Relative tolerance of the golden comparison. The cells are closed forms
/// and a fixed-step RK4 integration, deterministic up to libm and FMA
/// contraction (~1e-15 relative); any change of a formula, constant or time
/// grid moves them by far more than 1e-9.
constexpr double kGoldenRelTol = 1e-9;
/// Absolute floor of the same comparison, in the printed unit, for cells
/// that are exactly 0 (Figure 3.2 at t = 0).
constexpr double kGoldenAbsTol = 1e-12;
/// The golden file's numeric columns and their relative tolerances.
const std::map<std::string, double> kGoldenColumnRelTol = {{"computed", kGoldenRelTol}};

using Key = std::tuple<std::string, std::string, std::string>;

std::string source_dir() {
  if (const char* env = std::getenv("INSMC_SOURCE_DIR"); env != nullptr && *env != '\0') return env;
  return INSMC_DEFAULT_SOURCE_DIR;
}

std::filesystem::path golden_path(TableConvention c) {
  return std::filesystem::path(source_dir()) / "tests" / "regression" / "golden" /
         fmt::format("tables_{}.csv", to_string(c));
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) {
    if (ch == '"') q += '"';
    q += ch;
  }
  return q + "\"";
}

std::string golden_text(const std::vector<TableCell>& cells) {
  std::string out = "table,row,column,unit,computed\n";
  for (const auto& c : cells)
    out += fmt::format("{},{},{},{},{:.17g}\n", csv_field(c.table), csv_field(c.row), csv_field(c.column),
                       csv_field(c.unit), c.computed);
  return out;
}

void write_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    ASSERT_TRUE(f.good()) << "cannot write " << tmp;
  }
  std::filesystem::rename(tmp, path);
}

class TablesTest : public ::testing::TestWithParam<TableConvention> {
 protected:
  static const std::vector<TableCell>& cells(TableConvention c) {
    static std::map<TableConvention, std::vector<TableCell>> cache;
    auto it = cache.find(c);
    if (it == cache.end()) it = cache.emplace(c, compute_tables(ModelOptions{}, c)).first;
    return it->second;
  }
};

TEST(TablesTranscription, HasEveryPrintedCellOnce) {
  std::map<std::string, int> count;
  std::set<Key> seen;
  for (const auto& p : printed_cells()) {
    ++count[p.table];
    EXPECT_TRUE(seen.insert({p.table, p.row, p.column}).second)
        << "duplicate cell " << p.table << " / " << p.row << " / " << p.column;
    EXPECT_EQ(p.printed_digits, significant_digits(p.printed_text))
        << p.table << " / " << p.row << " / " << p.column << ": printed_digits of '" << p.printed_text << "'";
    EXPECT_FALSE(p.unit.empty()) << p.table << " / " << p.row;
    EXPECT_FALSE(p.source.empty()) << p.table << " / " << p.row;
  }
  EXPECT_EQ(count, kPrintedCellsPerTable);
}

TEST(TablesTranscription, SignificantDigitsAndRounding) {
  struct Case {
    const char* text;
    int digits;
    double half_ulp;
  };
  const Case cases[] = {{"1440", 3, 5.0},    {".015", 2, 0.0005}, {"3.0", 2, 0.05},  {"0", 0, 0.5},
                        {"21000", 2, 500.0}, {"49e-3", 2, 0.5e-3}, {"7.76e-6", 3, 0.005e-6}, {"1", 1, 0.5}};
  for (const Case& c : cases) {
    EXPECT_EQ(significant_digits(c.text), c.digits) << c.text;
    EXPECT_NEAR(half_unit_in_last_place(c.text), c.half_ulp, 1e-12 * c.half_ulp) << c.text;
  }
}

TEST_P(TablesTest, ComputesEveryPrintedCell) {
  const auto& computed = cells(GetParam());
  std::set<Key> printed_keys, computed_keys;
  std::map<Key, double> printed_value;
  for (const auto& p : printed_cells()) {
    printed_keys.insert({p.table, p.row, p.column});
    printed_value[{p.table, p.row, p.column}] = p.printed;
  }
  std::map<std::string, int> distinct_per_table;
  int figure = 0;
  for (const auto& c : computed) {
    EXPECT_TRUE(std::isfinite(c.computed)) << c.table << " / " << c.row << " / " << c.column;
    if (c.table == "fig3.2") {
      ++figure;
      EXPECT_FALSE(c.printed.has_value());
      continue;
    }
    const Key key{c.table, printed_row_key(c.row), c.column};
    ASSERT_TRUE(printed_keys.count(key)) << "computed cell without a printed one: " << c.table << " / " << c.row
                                         << " / " << c.column;
    ASSERT_TRUE(c.printed.has_value());
    EXPECT_EQ(*c.printed, printed_value[key]);
    if (computed_keys.insert(key).second) ++distinct_per_table[c.table];
  }
  for (const auto& k : printed_keys)
    EXPECT_TRUE(computed_keys.count(k)) << "printed cell not computed: " << std::get<0>(k) << " / "
                                        << std::get<1>(k) << " / " << std::get<2>(k);
  EXPECT_EQ(distinct_per_table, kPrintedCellsPerTable);
  EXPECT_EQ(figure, kFigureRows * kFigureColumns);
}

TEST_P(TablesTest, EveryDeviationBeyondThresholdHasANote) {
  int deviating = 0;
  for (const auto& c : cells(GetParam())) {
    if (!c.deviation_pct || std::abs(*c.deviation_pct) <= kNoteThresholdPct) continue;
    ++deviating;
    EXPECT_FALSE(c.note.empty()) << c.table << " / " << c.row << " / " << c.column << ": printed "
                                 << *c.printed << ", computed " << c.computed << " ("
                                 << fmt::format("{:+.1f}%", *c.deviation_pct)
                                 << ") needs a note in tables/notes/cell_notes.csv";
  }
  std::printf("[ %s ] %d cells deviate by more than %.0f%% from the printed value, all noted\n",
              std::string(to_string(GetParam())).c_str(), deviating, kNoteThresholdPct);
}

TEST_P(TablesTest, NoteClaimsHold) {
  const auto checks = check_note_claims(ModelOptions{}, GetParam());
  EXPECT_FALSE(checks.empty());
  for (const auto& k : checks)
    EXPECT_TRUE(k.holds) << k.table << " / " << k.row << " / " << k.column << " (" << k.kind << "): " << k.detail;
}

TEST_P(TablesTest, MatchesGolden) {
  const auto& computed = cells(GetParam());
  const auto path = golden_path(GetParam());
  if (const char* update = std::getenv("INSMC_UPDATE_GOLDEN"); update != nullptr && std::string(update) == "1") {
    write_atomically(path, golden_text(computed));
    std::printf("[ %s ] rewrote %s\n", std::string(to_string(GetParam())).c_str(), path.string().c_str());
    return;
  }
  std::ifstream f(path, std::ios::binary);
  ASSERT_TRUE(f.good()) << "no golden file " << path << "; create it with INSMC_UPDATE_GOLDEN=1";
  std::stringstream buffer;
  buffer << f.rdbuf();
  const auto records = parse_csv(buffer.str(), path.string());
  ASSERT_FALSE(records.empty());
  const auto& header = records[0];
  ASSERT_EQ(header, (std::vector<std::string>{"table", "row", "column", "unit", "computed"}));
  ASSERT_EQ(records.size() - 1, computed.size())
      << "cell count changed; if intended, rerun with INSMC_UPDATE_GOLDEN=1 and review the diff";
  for (std::size_t i = 0; i < computed.size(); ++i) {
    const auto& g = records[i + 1];
    const auto& c = computed[i];
    ASSERT_EQ(g.size(), header.size()) << path << " record " << i + 2;
    const std::vector<std::string> text = {c.table, c.row, c.column, c.unit};
    for (std::size_t j = 0; j < header.size(); ++j) {
      const auto tol = kGoldenColumnRelTol.find(header[j]);
      if (tol == kGoldenColumnRelTol.end()) {
        ASSERT_EQ(g[j], text[j]) << header[j] << " of record " << i + 2 << " of " << path;
        continue;
      }
      const double golden = std::stod(g[j]);
      const double now = c.computed;
      EXPECT_LE(std::abs(now - golden), tol->second * std::max(std::abs(now), std::abs(golden)) + kGoldenAbsTol)
          << c.table << " / " << c.row << " / " << c.column << ": " << header[j] << " "
          << fmt::format("{:.17g} vs golden {:.17g}", now, golden);
    }
  }
}

TEST_P(TablesTest, ReportsSignificantDigitAgreement) {
  struct Score {
    int scored = 0, all_digits = 0, within_one_digit = 0, beyond_threshold = 0;
    std::vector<double> lre;
  };
  std::map<std::string, int> digits;
  for (const auto& p : printed_cells()) digits[p.table + '\x1f' + p.row + '\x1f' + p.column] = p.printed_digits;
  std::map<std::string, Score> scores;
  for (const auto& c : cells(GetParam())) {
    if (!c.printed) continue;
    const auto lre = log_relative_error(c.computed, *c.printed);
    if (!lre) continue;
    Score& s = scores[c.table];
    const int d = digits[c.table + '\x1f' + printed_row_key(c.row) + '\x1f' + c.column];
    ++s.scored;
    s.lre.push_back(*lre);
    if (*lre >= d) ++s.all_digits;
    if (*lre >= d - 1) ++s.within_one_digit;
    if (c.deviation_pct && std::abs(*c.deviation_pct) > kNoteThresholdPct) ++s.beyond_threshold;
  }
  std::printf("[ %s ] significant-digit agreement (LRE = -log10|computed - printed|/|printed|):\n",
              std::string(to_string(GetParam())).c_str());
  std::printf("  table  cells  min LRE  median LRE  LRE>=digits  LRE>=digits-1  >%.0f%% (noted)\n",
              kNoteThresholdPct);
  for (auto& [table, s] : scores) {
    std::sort(s.lre.begin(), s.lre.end());
    std::printf("  %-5s  %5d  %7.2f  %10.2f  %11d  %13d  %5d\n", table.c_str(), s.scored, s.lre.front(),
                s.lre[s.lre.size() / 2], s.all_digits, s.within_one_digit, s.beyond_threshold);
    EXPECT_EQ(static_cast<std::size_t>(s.scored), s.lre.size());
  }
}

INSTANTIATE_TEST_SUITE_P(Conventions, TablesTest,
                         ::testing::Values(TableConvention::kPaper, TableConvention::kCorrected),
                         [](const ::testing::TestParamInfo<TableConvention>& info) {
                           return std::string(to_string(info.param));
                         });

}  // namespace
}  // namespace insmc::tables
