#include "lib/preflight/observables.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lib/propagation/closed_form.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

TEST(Observables, ShortFormOf44WithinTheReports10MicroGOver20Minutes) {
  // §4.1: (4.4) neglects terms giving less than 10 μg after 20 min at the
  // Table 3.1 maxima. Compare with the full (4.2) of the report's own model.
  const ModelOptions o;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const ShortRunMatrices m = paper_short_run_matrices(s, o);
    const LinearErrorModel full(s, o, LinearModelForm::as_printed());
    for (double t = 0; t <= 1200.0; t += 60.0) {
      const Sensitivity3 a = paper_accelerometer_error(m, t, o);
      const Sensitivity3 b = linear_accelerometer_error(full, t);
      for (int i = 0; i < uncertainty_slot::kDim; ++i) {
        const double diff_ug = (a.col(i) - b.col(i)).cwiseAbs().maxCoeff() * default_bounds()[i] / kUgToMps2;
        EXPECT_LT(diff_ug, 10.0) << "system " << system_number(s) << " t=" << t << " "
                                 << testing::name_of(i);
      }
    }
  }
}

TEST(Observables, TestRunPositionOf45Within100FeetOver20Minutes) {
  // §4.2: (4.5) neglects terms under 100 ft for test runs under 20 min.
  const ModelOptions o;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const ShortRunMatrices m = paper_short_run_matrices(s, o);
    const LinearErrorModel full(s, o, LinearModelForm::as_printed());
    std::vector<double> times;
    for (double t = 60.0; t <= 1200.0; t += 60.0) times.push_back(t);
    const auto maps = linear_position_maps(full, times);
    for (size_t n = 0; n < times.size(); ++n) {
      const Sensitivity3 delta_r = maps[n] - full.initial_position();
      const Sensitivity3 a = paper_test_position_change(m, times[n], o);
      for (int i = 0; i < uncertainty_slot::kDim; ++i) {
        EXPECT_LT(testing::difference_at_bound_ft(a, delta_r, i), 100.0)
            << "system " << system_number(s) << " t=" << times[n] << " " << testing::name_of(i);
      }
    }
  }
}

TEST(Observables, PositionIsTheDoubleIntegralOfTheAccelerometerErrorForShortTests) {
  // §4.3: below 15 min, Δr ≈ δV(0) t + ∬ Δf, with Δf of (4.4) less the
  // δr(0)/r0 part of A1 (4.4b). The largest relative remainder of the four
  // series is that of sin ω_s t ≈ ω_s t: x/sin x − 1.
  const ModelOptions o;
  const ShortRunMatrices m = paper_short_run_matrices(System::kTheodolite, o);
  const double g = o.gravity_mps2, w = o.earth_rate_radps;
  for (double t = 60.0; t <= 900.0; t += 60.0) {
    const Sensitivity3 integrated = t * m.initial_velocity_mps +
                                    g * (t * t / 2 * m.u2 + w * t * t * t / 6 * m.u3 +
                                         w * w * t * t * t * t / 24 * m.u4);
    const Sensitivity3 exact = paper_test_position_change(m, t, o);
    const double x = o.schuler_radps() * t;
    for (int i = 0; i < uncertainty_slot::kDim; ++i) {
      const double scale = exact.col(i).cwiseAbs().maxCoeff() + 1e-300;
      EXPECT_LE((integrated.col(i) - exact.col(i)).cwiseAbs().maxCoeff() / scale, x / std::sin(x) - 1 + 1e-12)
          << testing::name_of(i);
    }
  }
}

TEST(Observables, ResolutionLimitsOf46) {
  const ModelOptions o;
  const auto r = pulse_resolution_limits(0.1 * kFtToM, 600.0, o);
  // Table 4.3, T = 10 min: 15.5e-6, 0.71e-3, 49e-3.
  EXPECT_NEAR(r.a1, 15.5e-6, 0.1e-6);
  EXPECT_NEAR(r.u3, 0.71e-3, 0.01e-3);
  EXPECT_NEAR(r.u4, 49e-3, 0.5e-3);
}

}  // namespace
}  // namespace insmc
