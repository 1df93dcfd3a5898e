// The screen of the r rows the model does not read: a smooth error
// quantized by the position computer stays within its reach; a corrupt
// value between two read rows is found; a read row is left to the
// residuals (outliers.h).
#include "montecarlo/records/gap/where/unread_rows.h"

#include <gtest/gtest.h>

#include <cmath>

namespace insmc::gap {
namespace {

constexpr double kResolution_m = 0.9144;  // 3 ft
constexpr double kStep_s = 10, kReadStep_s = 30, kEnd_s = 3600;

/// A run of r every 10 s: a slow quadratic drift and a Schuler swing on
/// each axis, quantized to 3 ft; the model reads one row per 30 s.
struct OneRun {
  RecordFile file;
  std::vector<runs::RunData> runs;
};

OneRun smooth_run() {
  OneRun o;
  RecordRun run;
  run.id = 7;
  runs::RunData data;
  data.id = 7;
  for (double t = 0; t <= kEnd_s; t += kStep_s) {
    RecordRow row;
    row.run = 7;
    row.t_s = t;
    row.phase = t <= 900 ? Phase::kTest : Phase::kNav;
    Eigen::Vector3d r;
    for (int k = 0; k < 3; ++k) {
      const double smooth = 1e-3 * (k + 1) * t * t / 2 + 400.0 * std::sin(1.24e-3 * t + k);
      r[k] = kResolution_m * std::round(smooth / kResolution_m);
    }
    row.r_ap_m = r;
    run.rows.push_back(row);
    if (std::fmod(t, kReadStep_s) == 0)
      for (int k = 0; k < 3; ++k) data.layout.rows.push_back({t, runs::Quantity::kR, k, 0});
  }
  o.file.runs.push_back(run);
  o.runs.push_back(data);
  return o;
}

TEST(UnreadRows, ASmoothQuantizedErrorStaysWithinItsReach) {
  const OneRun o = smooth_run();
  const UnreadRows u = screen_unread_rows(o.file, o.runs, kResolution_m);
  EXPECT_EQ(u.read, 121);
  EXPECT_EQ(u.unread, 240);
  EXPECT_EQ(u.beyond, 0);
  EXPECT_FALSE(unread_rows_isolated(u));
  EXPECT_NE(unread_rows_sentence(u).find("240 were screened"), std::string::npos) << unread_rows_sentence(u);
  EXPECT_NE(unread_rows_sentence(u).find("none leaves it"), std::string::npos);
}

TEST(UnreadRows, ACorruptValueBetweenReadRowsIsFoundAndOneOnAReadRowIsLeftToTheResiduals) {
  // t = 1210 s is not read (1210 / 30 is not whole).
  OneRun o = smooth_run();
  ASSERT_EQ(o.file.runs[0].rows[121].t_s, 1210.0);
  (*o.file.runs[0].rows[121].r_ap_m)[1] += 50.0;
  const UnreadRows u = screen_unread_rows(o.file, o.runs, kResolution_m);
  ASSERT_EQ(u.beyond, 1);
  EXPECT_EQ(u.runs_beyond, 1);
  EXPECT_TRUE(unread_rows_isolated(u));
  ASSERT_EQ(u.largest.size(), 1u);
  EXPECT_EQ(u.largest[0].run, 7);
  EXPECT_EQ(u.largest[0].t_s, 1210.0);
  EXPECT_EQ(u.largest[0].component, "r_y");
  EXPECT_NEAR(u.largest[0].deviation_m, 50.0, 2 * kResolution_m);
  // The bound: ten times q plus the curvature's reach a·10 s·20 s/2, a at
  // most about 3e-3 m/s² of the error and 4q/(30 s · 60 s) of the read
  // rows' own quantization: between 10 q and 10 (q + 0.6 m).
  EXPECT_GT(u.largest[0].bound_m, 10 * kResolution_m);
  EXPECT_LT(u.largest[0].bound_m, 10 * (kResolution_m + 0.6));
  EXPECT_NE(unread_rows_finding(u).find("An r value of one run"), std::string::npos) << unread_rows_finding(u);
  EXPECT_NE(unread_rows_sentence(u).find("1 leaves it in 1 of 1 runs"), std::string::npos) << unread_rows_sentence(u);

  // The same spike on a read row (t = 1200 s) is the residuals' to judge
  // (outliers.h): it widens its neighbours' reach, and nothing is listed.
  OneRun on_read = smooth_run();
  (*on_read.file.runs[0].rows[120].r_ap_m)[1] += 50.0;
  const UnreadRows r = screen_unread_rows(on_read.file, on_read.runs, kResolution_m);
  EXPECT_EQ(r.read, 121);
  EXPECT_EQ(r.beyond, 0);
  EXPECT_EQ(unread_rows_finding(r), "");
}

TEST(UnreadRows, EveryRowReadIsNothingToSay) {
  OneRun o = smooth_run();
  o.runs[0].layout.rows.clear();
  for (const RecordRow& row : o.file.runs[0].rows)
    for (int k = 0; k < 3; ++k) o.runs[0].layout.rows.push_back({row.t_s, runs::Quantity::kR, k, 0});
  const UnreadRows u = screen_unread_rows(o.file, o.runs, kResolution_m);
  EXPECT_EQ(u.unread, 0);
  EXPECT_EQ(unread_rows_sentence(u), "");
}

}  // namespace
}  // namespace insmc::gap
