// What a random-process candidate adds to the f rows beside its knots and
// bridge mode (montecarlo/records/gap/candidates/random_process.h), against closed
// forms derived independently: the Brownian bridge's covariance
// q (min(s, s') − s s'/Δ) for the drift's remainder, and δf = δθ × f with
// the specific force of the space-stabilized platform for a tilt.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lib/uncertainty/uncertainty_model.h"
#include "lib/units/units.h"
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/random_process.h"
#include "montecarlo/records/runs/model/gaussian_model.h"
#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::gap::candidates {
namespace {

struct Context {
  runs::Layout layout = runs::testing::test_layout(6300.0);
  runs::RecordSite site;
  runs::BaseModel base;
  LayoutContext ctx;
  Context() {
    site.filter_interval_s = 10.0;
    base = make_base_model(layout, site, UncertaintyModel{}.variance());
    ctx = {&layout, &site, &base, {}};
  }
};

/// Σ_k of what a unit angle variance about each axis puts on f_k: |f|² − f_k².
double tilt_weight(const runs::ObservationRow& row, const ModelOptions& m) {
  const Eigen::Vector3d f = specific_force(row.t_s, m);
  return f.squaredNorm() - f[row.axis] * f[row.axis];
}

TEST(RandomProcess, ATiltReachesTheVerticalAccelerometerAsGravityTurnsInThePlatform) {
  const Context c;
  const Eigen::VectorXd add = tilt_f_noise(c.ctx, 1.0);
  const double g = c.site.model.gravity_mps2;
  bool vertical_seen = false;
  for (std::size_t i = 0; i < c.layout.rows.size(); ++i) {
    const runs::ObservationRow& row = c.layout.rows[i];
    const double got = add[static_cast<Eigen::Index>(i)];
    if (row.quantity != runs::Quantity::kF) {
      EXPECT_EQ(got, 0.0);
      continue;
    }
    // |f| is g at every time; the horizontal axes see all of it at switch-over.
    EXPECT_NEAR(got, tilt_weight(row, c.site.model), 1e-12 * g * g);
    if (row.t_s <= 10.0) {
      EXPECT_NEAR(got, row.axis == 2 ? 0.0 : g * g, 1e-3 * g * g) << row.axis;
    }
    // After 105 min at 45°, the earth has turned the vertical by tens of
    // milliradians in the platform: f_z sees a tilt.
    if (row.axis == 2 && row.t_s > 6000.0) vertical_seen = vertical_seen || got > 1e-4 * g * g;
  }
  EXPECT_TRUE(vertical_seen);
}

TEST(RandomProcess, ADriftsRemainderOnTheFRowsIsTheBridgeVarianceLessItsFirstMode) {
  // Random-walk drift (τ = 0) of σ after 1 h: q = σ²/3600. Over an interval
  // of Δ the bridge's ∫ has variance q(u³/3 − u⁴/(4Δ)) at u, mode 1 carries
  // 2qΔ/π² ((1 − cos(πu/Δ)) Δ/π)². Averaged over u the difference is
  // qΔ³(1/30 − 3/π⁴); at the interval's end qΔ³(1/12 − 8/π⁴), which adds up
  // from interval to interval.
  const Context c;
  const double sigma = 1.0 * kMeruToRadps, q = sigma * sigma / 3600.0;
  const runs::Extension e = process_extension(c.ctx, Drive::kRate, sigma, 0.0);
  const double d = std::max(kMinKnotSpacingS, 6300.0 / kMaxKnots), d3 = d * d * d;
  const double pi4 = std::pow(std::numbers::pi, 4);
  const double mean = q * d3 * (1.0 / 30.0 - 3.0 / pi4), per_interval = q * d3 * (1.0 / 12.0 - 8.0 / pi4);
  ASSERT_EQ(e.noise_var_add.size(), static_cast<Eigen::Index>(c.layout.rows.size()));
  for (std::size_t i = 0; i < c.layout.rows.size(); ++i) {
    const runs::ObservationRow& row = c.layout.rows[i];
    if (row.quantity != runs::Quantity::kF) continue;
    const double want = (mean + per_interval * row.t_s / d) * tilt_weight(row, c.site.model);
    EXPECT_NEAR(e.noise_var_add[static_cast<Eigen::Index>(i)], want, 1e-9 * want) << row.t_s;
  }
}

TEST(RandomProcess, AnAngleRandomWalksRemainderGoesThroughTheSameTilt) {
  const Context c;
  const double sigma = 0.1 * kMradToRad;
  const runs::Extension e = process_extension(c.ctx, Drive::kAngle, sigma, 0.0);
  const Eigen::VectorXd unit = tilt_f_noise(c.ctx, 1.0);
  // The same shape as a unit tilt, scaled by the bridge's white remainder.
  double scale = 0;
  for (Eigen::Index i = 0; i < unit.size(); ++i)
    if (unit[i] > 0) {
      if (scale == 0) scale = e.noise_var_add[i] / unit[i];
      EXPECT_NEAR(e.noise_var_add[i], scale * unit[i], 1e-9 * scale * unit[i]);
    }
  EXPECT_GT(scale, 0.0);
}

}  // namespace
}  // namespace insmc::gap::candidates
