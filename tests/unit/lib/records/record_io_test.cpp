#include "lib/records/record_io.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "lib/common/input_error.h"
#include "lib/records/record.h"

namespace insmc {
namespace {

namespace fs = std::filesystem;

/// Joins lines with "\n" and ends with one.
std::string join(const std::vector<std::string>& lines, std::string_view eol = "\n") {
  std::string out;
  for (const auto& l : lines) {
    out += l;
    out += eol;
  }
  return out;
}

/// A small valid file; line numbers are those of the comments.
std::vector<std::string> good_lines() {
  return {
      "# insmc-record v1",                         // 1
      "# latitude_deg=45",                         // 2
      "# system=1",                                // 3
      "# test_duration_s=900",                     // 4
      "# scheme=none",                             // 5
      "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z",     // 6
      "1,-10,align,0.1,0.2,0.3,,,",                // 7
      "1,0,test,1e-5,,2e-5,1,2,3",                 // 8
      "1,900,test,,,,1.5,2.5,3.5",                 // 9
      "1,960,nav,,,,4,5,6",                        // 10
      "2,0,test,,,,1,1,1",                         // 11
  };
}

class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("insmc_records_test_" + std::to_string(std::random_device{}()) + "_" +
             std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  fs::path write(const std::string& name, const std::string& content) const {
    const fs::path p = path_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }

 private:
  fs::path path_;
};

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || same_bits(*a, *b));
}

void expect_bit_identical(const RecordFile& a, const RecordFile& b) {
  EXPECT_EQ(a.header, b.header);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) {
    ASSERT_EQ(a.runs[i].id, b.runs[i].id);
    ASSERT_EQ(a.runs[i].rows.size(), b.runs[i].rows.size());
    for (std::size_t j = 0; j < a.runs[i].rows.size(); ++j) {
      const RecordRow& x = a.runs[i].rows[j];
      const RecordRow& y = b.runs[i].rows[j];
      EXPECT_EQ(x.run, y.run);
      EXPECT_TRUE(same_bits(x.t_s, y.t_s)) << x.t_s << " vs " << y.t_s;
      EXPECT_EQ(x.phase, y.phase);
      ASSERT_EQ(x.r_ap_m.has_value(), y.r_ap_m.has_value());
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(same_bits(x.f_mps2[k], y.f_mps2[k]));
        EXPECT_TRUE(same_bits(x.w_radps[k], y.w_radps[k]));
        if (x.r_ap_m) {
          EXPECT_TRUE(same_bits((*x.r_ap_m)[k], (*y.r_ap_m)[k])) << (*x.r_ap_m)[k];
        }
      }
    }
  }
}

/// Any finite double within the reader's caps on row values (|v| <= 1000,
/// the smallest: w), drawn from its bit pattern (all exponents below the cap
/// equally likely: tiny, subnormal, negative, ±0); a larger one keeps its
/// mantissa and sign with an exponent below 10.
double random_finite(std::mt19937_64& rng) {
  while (true) {
    double v = std::bit_cast<double>(rng());
    if (!std::isfinite(v)) continue;
    if (std::abs(v) > kMaxRecordAbsWRadps) {
      int e = 0;
      const double m = std::frexp(v, &e);
      v = std::ldexp(m, e % 10);
    }
    return v;
  }
}

std::optional<double> maybe(std::mt19937_64& rng, double v) {
  return rng() % 4 == 0 ? std::nullopt : std::optional<double>(v);
}

RecordFile random_file(std::mt19937_64& rng) {
  constexpr double kT = 900.0;
  RecordFile file;
  file.header = RecordHeader::make(-33.8765432109876, System::kGyrocompass, kT, Scheme::k5_1_1);
  file.header.set("dv_pulse_mps", 0.03048);
  file.header.set("position_resolution_m", 0.1);
  file.header.set("nav_start_s", 1234.5);
  file.header.set("site", "somewhere else");
  file.header.set("truth.effect.sway", "amplitude=1e-3");
  file.header.set("truth.seed", "17");
  // In the order of their numbers, the reader's (runs in another order:
  // RunsAreTakenInTheOrderOfTheirNumbers).
  const std::int64_t ids[] = {std::numeric_limits<std::int64_t>::min(), -3, 0, 7, 1'000'000'007,
                              std::numeric_limits<std::int64_t>::max()};
  const double specials[] = {0.0, -0.0, 5e-324, -5e-324, std::numeric_limits<double>::min(),
                             kMaxRecordAbsWRadps, -kMaxRecordAbsWRadps, std::nextafter(kMaxRecordAbsWRadps, 0.0),
                             1e-300, -999.9999999999999, 0.1, 1.0 / 3.0, 45.0};
  for (std::int64_t id : ids) {
    RecordRun run{id, {}};
    auto value = [&]() {
      return rng() % 3 == 0 ? specials[rng() % std::size(specials)] : random_finite(rng);
    };
    // Times: the hard edges of each window plus random values inside them.
    std::vector<std::pair<double, Phase>> times = {{-600.0, Phase::kAlign},
                                                   {-1.0 / 3.0, Phase::kAlign},
                                                   {-5e-324, Phase::kAlign},
                                                   {-0.0, Phase::kTest},
                                                   {5e-324, Phase::kTest},
                                                   {std::nextafter(kT, 0.0), Phase::kTest},
                                                   {kT, Phase::kTest},
                                                   {std::nextafter(kT, 1e9), Phase::kNav}};
    double t = kT + 1.0;
    for (int i = 0; i < 20; ++i) {
      t += std::ldexp(static_cast<double>(rng() % 1000 + 1), -static_cast<int>(rng() % 20));
      times.emplace_back(t, Phase::kNav);
    }
    for (const auto& [t_s, phase] : times) {
      RecordRow row;
      row.run = id;
      row.t_s = t_s;
      row.phase = phase;
      for (int k = 0; k < 3; ++k) row.f_mps2[k] = maybe(rng, value());
      if (phase == Phase::kAlign) {
        for (int k = 0; k < 3; ++k) row.w_radps[k] = maybe(rng, value());
      }
      if (phase != Phase::kAlign || rng() % 2 == 0) row.r_ap_m = Eigen::Vector3d(value(), value(), value());
      run.rows.push_back(row);
    }
    file.runs.push_back(std::move(run));
  }
  return file;
}

TEST(RecordIo, RoundTripIsBitIdentical) {
  std::mt19937_64 rng(20240611);
  for (int trial = 0; trial < 20; ++trial) {
    const RecordFile original = random_file(rng);
    const std::string text = write_record_file(original);
    const RecordFile back = parse_record_text(text, "mem");
    EXPECT_EQ(back, original);
    expect_bit_identical(back, original);
    EXPECT_EQ(write_record_file(back), text);  // and the text is a fixed point
  }
}

TEST(RecordIo, RoundTripThroughAFile) {
  TempDir dir;
  std::mt19937_64 rng(7);
  const RecordFile original = random_file(rng);
  const fs::path p = dir.write("r.csv", write_record_file(original));
  expect_bit_identical(read_record_file(p), original);
}

TEST(RecordIo, WriterOmitsWColumnsWhenUnused) {
  RecordFile file{RecordHeader::make(45, System::kTheodolite, 900, Scheme::kNone), {}};
  RecordRow row;
  row.run = 1;
  row.t_s = 0.5;
  row.r_ap_m = Eigen::Vector3d(1, 2, 3);
  file.runs.push_back(RecordRun{1, {row}});
  EXPECT_EQ(write_record_file(file),
            "# insmc-record v1\n# latitude_deg=45\n# system=1\n# test_duration_s=900\n# scheme=none\n"
            "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z\n1,0.5,test,,,,1,2,3\n");
}

TEST(RecordHeaderTest, TypedAccessors) {
  const RecordFile f = parse_record_text(join(good_lines()), "mem");
  EXPECT_EQ(f.header.latitude_deg(), 45.0);
  EXPECT_EQ(f.header.system(), System::kTheodolite);
  EXPECT_EQ(f.header.test_duration_s(), 900.0);
  EXPECT_EQ(f.header.scheme(), Scheme::kNone);
  EXPECT_FALSE(f.header.dv_pulse_mps());
  EXPECT_FALSE(f.header.position_resolution_m());
  EXPECT_FALSE(f.header.nav_start_s());
  RecordHeader h = f.header;
  h.set("dv_pulse_mps", 0.0);
  h.set("nav_start_s", "1.2e3");
  EXPECT_EQ(h.dv_pulse_mps(), 0.0);
  EXPECT_EQ(h.nav_start_s(), 1200.0);
  h.set("system", "7");
  EXPECT_THROW(h.system(), InputError);
  RecordHeader empty;
  EXPECT_THROW(empty.latitude_deg(), InputError);
  EXPECT_THROW(empty.scheme(), InputError);
}

TEST(RecordHeaderTest, TruthKeysAreKeptApartAndStripped) {
  std::vector<std::string> lines = good_lines();
  lines.insert(lines.begin() + 2, "# truth.effect.accel_bias_instability=sigma=5e-05,tau=600");
  lines.insert(lines.begin() + 4, "# operator=someone");
  lines.insert(lines.begin() + 5, "# truth.seed=3");
  const RecordFile f = parse_record_text(join(lines), "mem");
  ASSERT_EQ(f.header.truth_entries.size(), 2u);
  EXPECT_EQ(f.header.truth_entries[0],
            (HeaderEntry{"truth.effect.accel_bias_instability", "sigma=5e-05,tau=600"}));
  EXPECT_EQ(f.header.truth_entries[1], (HeaderEntry{"truth.seed", "3"}));
  for (const auto& e : f.header.entries) EXPECT_FALSE(e.key.starts_with("truth.")) << e.key;
  ASSERT_NE(f.header.find("operator"), nullptr);
  EXPECT_EQ(*f.header.find("truth.seed"), "3");

  const RecordHeader visible = f.header.without_truth();
  EXPECT_TRUE(visible.truth_entries.empty());
  EXPECT_EQ(visible.entries, f.header.entries);
  EXPECT_EQ(visible.find("truth.seed"), nullptr);

  const std::string stripped = write_record_file(f, TruthKeys::kStrip);
  EXPECT_EQ(stripped.find("truth."), std::string::npos);
  const RecordFile back = parse_record_text(stripped, "mem");
  EXPECT_EQ(back, without_truth(f));
  EXPECT_EQ(back.runs, f.runs);
  EXPECT_NE(write_record_file(f).find("# truth.seed=3\n"), std::string::npos);
}

TEST(RecordIo, AcceptsRecordsOtherSoftwareWrote) {
  // BOM, CRLF, trailing blanks, blank lines, keys and columns in any order,
  // unknown keys, extra and quoted columns, numbers as 45 / 45.0 / 45.000 /
  // 4.5e1 / +4.5e+1, interleaved runs with arbitrary numbers, f components
  // missing on their own, a subset of the w columns, trailing empty lines.
  const std::vector<std::string> lines = {
      "\xEF\xBB\xBF# insmc-record v1  ",
      "# scheme=5.2",
      "#   test_duration_s = 900.000 ",
      "# instrument=ADIS16405",
      "# system=2",
      "# latitude_deg=4.5e1",
      "",
      "phase,\"run\",temp_C,r_z,r_y,r_x,f_z,f_y,f_x,t_s,w_y",
      "align,1007,21.5,,,,0.1,,0.3,-5,1e-6",
      "test,1007,21.5,3,2,1,,,,0,",
      "test,-4,20.0,30,20,10,,,,0.0,",
      "test,1007,21.6,3.000,2.0,1,,2e-5,,45,",
      "nav,-4,20.0,30,20,10,,,,+9.6e+2 ,  ",
      "nav,-4 ,20.0, 1 , 2 , 3 ,,,,4.5e3,",
      "test,42.0,20,0,0,0,,,,900,",
      "",
      "",
  };
  for (std::string_view eol : {"\n", "\r\n"}) {
    const RecordFile f = parse_record_text(join(lines, eol), "other.csv");
    EXPECT_EQ(f.header.latitude_deg(), 45.0);
    EXPECT_EQ(f.header.system(), System::kGyrocompass);
    EXPECT_EQ(f.header.test_duration_s(), 900.0);
    EXPECT_EQ(f.header.scheme(), Scheme::k5_2);
    ASSERT_NE(f.header.find("instrument"), nullptr);
    EXPECT_EQ(*f.header.find("instrument"), "ADIS16405");
    EXPECT_EQ(f.header.entries.front().key, "scheme");  // order kept as given
    ASSERT_EQ(f.runs.size(), 3u);
    EXPECT_EQ(f.runs[0].id, -4);  // in the order of their numbers
    EXPECT_EQ(f.runs[1].id, 42);
    EXPECT_EQ(f.runs[2].id, 1007);
    ASSERT_EQ(f.runs[2].rows.size(), 3u);
    const RecordRow& a = f.runs[2].rows[0];
    EXPECT_EQ(a.phase, Phase::kAlign);
    EXPECT_EQ(a.t_s, -5.0);
    EXPECT_FALSE(a.r_ap_m);
    EXPECT_EQ(a.f_mps2[0], 0.3);
    EXPECT_FALSE(a.f_mps2[1]);
    EXPECT_EQ(a.f_mps2[2], 0.1);
    EXPECT_FALSE(a.w_radps[0]);
    EXPECT_EQ(a.w_radps[1], 1e-6);
    EXPECT_EQ(f.runs[2].rows[2].r_ap_m, Eigen::Vector3d(1, 2, 3));
    EXPECT_EQ(f.runs[2].rows[2].f_mps2[1], 2e-5);
    ASSERT_EQ(f.runs[0].rows.size(), 3u);
    EXPECT_EQ(f.runs[0].rows[1].t_s, 960.0);
    EXPECT_EQ(f.runs[0].rows[1].phase, Phase::kNav);
    EXPECT_EQ(f.runs[0].rows[2].r_ap_m, Eigen::Vector3d(3, 2, 1));
    EXPECT_EQ(f.runs[0].rows[2].t_s, 4500.0);
    for (const auto& run : f.runs) {
      for (const auto& row : run.rows) EXPECT_EQ(row.run, run.id);
    }
  }
}

TEST(RecordIo, RunsAreTakenInTheOrderOfTheirNumbers) {
  // The same runs written in another order (reversed, each run whole, or
  // rows interleaved) read as the same file: what is drawn per run follows
  // the run, not its place in the file.
  std::mt19937_64 rng(11);
  const RecordFile original = random_file(rng);
  RecordFile reversed = original;
  std::reverse(reversed.runs.begin(), reversed.runs.end());
  ASSERT_NE(reversed.runs.front().id, original.runs.front().id);
  const RecordFile back = parse_record_text(write_record_file(reversed), "reversed.csv");
  expect_bit_identical(back, original);
}

TEST(RecordIo, AcceptsMissingFinalNewline) {
  std::string text = join(good_lines());
  text.pop_back();
  EXPECT_EQ(parse_record_text(text, "m").runs.size(), 2u);
}

TEST(RecordIo, TheLastTestRowMayBeStampedPastTByARecordersJitter) {
  // Rows every 10 s; the one at T = 900 s stamped 0.05 s late (0.5 % of
  // its spacing) is the row at T. 2 s late (20 %) it is refused.
  std::vector<std::string> lines = good_lines();
  lines.resize(6);  // the header and the column names
  lines.push_back("1,890,test,,,,1,2,3");
  lines.push_back("1,900.05,test,,,,1,2,3");
  lines.push_back("1,910,nav,,,,1,2,3");
  EXPECT_EQ(parse_record_text(join(lines), "jitter.csv").runs.front().rows.size(), 3u);
  lines[7] = "1,902,test,,,,1,2,3";
  EXPECT_THROW(parse_record_text(join(lines), "late.csv"), InputError);
}

struct BadCase {
  const char* name;
  std::vector<std::string> lines;
  int line;
  int column;
  const char* expected;  ///< a substring of the message after "FILE:LINE:COLUMN: "
};

/// good_lines() with line `n` (1-based) replaced by `text`.
std::vector<std::string> with_line(int n, std::string text) {
  auto lines = good_lines();
  lines[static_cast<std::size_t>(n - 1)] = std::move(text);
  return lines;
}
std::vector<std::string> without_line(int n) {
  auto lines = good_lines();
  lines.erase(lines.begin() + (n - 1));
  return lines;
}
std::vector<std::string> with_appended(std::vector<std::string> extra) {
  auto lines = good_lines();
  lines.insert(lines.end(), extra.begin(), extra.end());
  return lines;
}
/// good_lines() with `text` inserted before line `n`.
std::vector<std::string> with_inserted(int n, std::string text) {
  auto lines = good_lines();
  lines.insert(lines.begin() + (n - 1), std::move(text));
  return lines;
}
/// The first `n` lines of good_lines().
std::vector<std::string> first_lines(std::size_t n) {
  auto lines = good_lines();
  lines.resize(n);
  return lines;
}

TEST(RecordIo, BadFilesGiveFileLineColumn) {
  const std::vector<BadCase> cases = {
      {"empty", {}, 1, 1, "empty file"},
      {"version", with_line(1, "# insmc-record v2"), 1, 16, "unsupported record format version 'v2'"},
      {"no_version", with_line(1, "# insmc-record"), 1, 15, "missing format version"},
      {"not_a_record", with_line(1, "run,t_s"), 1, 1, "not an insmc record file"},
      {"header_no_equals", with_line(2, "# latitude_deg 45"), 2, 3, "is not '# key=value'"},
      {"header_empty_key", with_line(2, "# =45"), 2, 3, "empty key"},
      {"duplicate_key", with_line(5, "# system=1"), 5, 3, "duplicate header key 'system' (first given on line 3)"},
      {"missing_key", without_line(3), 5, 1, "missing required header key 'system'"},
      {"latitude_range", with_line(2, "# latitude_deg=95"), 2, 16, "must be in [-90, 90]"},
      {"latitude_nan", with_line(2, "# latitude_deg=nan"), 2, 16, "not finite"},
      {"latitude_text", with_line(2, "# latitude_deg=45N"), 2, 16, "not a number"},
      {"system", with_line(3, "# system=3"), 3, 10, "must be 1 (theodolite azimuth) or 2"},
      {"duration_negative", with_line(4, "# test_duration_s=-900"), 4, 19, "must be in (0, 172800]"},
      {"duration_empty", with_line(4, "# test_duration_s="), 4, 19, "not a number"},
      {"scheme", with_line(5, "# scheme=5.9"), 5, 10, "must be one of: none, 5.1.1"},
      {"dv_pulse_negative", with_inserted(6, "# dv_pulse_mps=-0.1"), 6, 16, "dv_pulse_mps = '-0.1': must be 0 (a continuous output) or in [1e-06, 10]"},
      {"nav_start_text", with_inserted(6, "# nav_start_s=soon"), 6, 15, "nav_start_s = 'soon': must be a finite"},
      {"missing_column", with_line(6, "run,t_s,phase,f_x,f_y,f_z,r_x,r_y"), 6, 1, "missing column(s) r_z"},
      {"missing_columns", with_line(6, "run,t_s,f_x,f_y,f_z,r_x,r_y"), 6, 1, "missing column(s) phase, r_z"},
      {"duplicate_column", with_line(6, "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z,t_s"), 6, 39, "duplicate column 't_s'"},
      {"no_column_header", first_lines(5), 6, 1, "missing the column header line"},
      {"no_rows", first_lines(6), 7, 1, "no data rows"},
      {"non_numeric", with_line(8, "1,0,test,abc,,2e-5,1,2,3"), 8, 10, "f_x = 'abc': not a number"},
      {"comma_decimal", with_line(8, "1,0,test,1e-5,,2e-5,1,2;5,3"), 8, 23, "r_y = '2;5': not a number"},
      {"nan_r", with_line(8, "1,0,test,,,,NaN,2,3"), 8, 13, "r_x = 'NaN': not finite"},
      {"inf_t", with_line(9, "1,inf,test,,,,1,2,3"), 9, 3, "t_s = 'inf': not finite"},
      {"huge_f", with_line(8, "1,0,test,1e400,,,1,2,3"), 8, 10, "out of the range"},
      {"empty_t", with_line(9, "1,,test,,,,1,2,3"), 9, 3, "t_s is empty"},
      {"too_few_fields", with_line(8, "1,0,test,,,,1,2"), 8, 16, "8 fields, but the column header (line 6) has 9"},
      {"too_many_fields", with_line(8, "1,0,test,,,,1,2,3,4"), 8, 18, "10 fields"},
      {"bad_phase", with_line(9, "1,900,flight,,,,1,2,3"), 9, 7, "phase = 'flight': must be one of"},
      {"run_not_integer", with_line(9, "1.5,900,test,,,,1,2,3"), 9, 1, "run = '1.5': not an integer"},
      {"run_empty", with_line(9, ",900,test,,,,1,2,3"), 9, 1, "run is empty"},
      {"time_not_increasing", with_line(9, "1,0,test,,,,1,2,3"), 9, 3, "t_s = 0 is not after the previous row of run 1"},
      {"phase_order", with_appended({"1,970,test,,,,1,2,3"}), 12, 7, "phase 'test' after 'nav' in run 1"},
      {"align_after_test", with_line(9, "1,1,align,,,,1,2,3"), 9, 5, "phase 'align' after 'test'"},
      {"align_time", with_line(7, "1,0,align,,,,,,"), 7, 3, "alignment rows need t_s < 0"},
      {"test_time", with_line(9, "1,950,test,,,,1,2,3"), 9, 3, "test rows need 0 <= t_s <= test_duration_s = 900"},
      {"nav_time", with_appended({"2,900,nav,,,,1,1,1"}), 12, 3, "nav rows need t_s > test_duration_s = 900"},
      {"missing_r", with_line(10, "1,960,nav,1,2,3,,,"), 10, 17, "r is required on test and nav rows"},
      {"partial_r", with_line(10, "1,960,nav,,,,4,,6"), 10, 16, "r_y is empty but r_x is not"},
      {"interleaved_time", with_appended({"2,0.5,test,,,,1,1,1", "1,950,nav,,,,1,1,1"}), 13, 3,
       "is not after the previous row of run 1"},
      {"only_align", with_appended({"9,-1,align,,,,,,"}), 12, 1, "run 9 has only align rows"},
      {"header_after_columns", with_appended({"# late=1"}), 12, 1, "header line after the column header (line 6)"},
  };
  TempDir dir;
  int checked = 0;
  for (const BadCase& c : cases) {
    const fs::path p = dir.write(std::string(c.name) + ".csv", join(c.lines));
    const std::string prefix = fmt::format("{}:{}:{}: ", p.string(), c.line, c.column);
    try {
      read_record_file(p);
      ADD_FAILURE() << c.name << ": no error";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_TRUE(msg.starts_with(prefix)) << c.name << ": expected prefix '" << prefix << "' in: " << msg;
      EXPECT_NE(msg.find(c.expected), std::string::npos) << c.name << ": expected '" << c.expected << "' in: " << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << c.name << ": message is not one line: " << msg;
      ++checked;
    }
  }
  EXPECT_GE(checked, 15);
}

TEST(RecordIo, MissingFileIsAnInputError) {
  TempDir dir;
  const fs::path p = dir.write("x.csv", "").parent_path() / "does_not_exist.csv";
  try {
    read_record_file(p);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
  }
}

TEST(RecordIo, PhaseNames) {
  for (Phase p : {Phase::kAlign, Phase::kTest, Phase::kNav}) EXPECT_EQ(parse_phase(to_string(p)), p);
  EXPECT_THROW(parse_phase("Test"), InputError);
}

}  // namespace
}  // namespace insmc
