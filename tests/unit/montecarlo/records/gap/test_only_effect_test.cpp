// An effect defined outside the library (here, in this test) with its
// diagnosis candidate is one definition each and one registration each: the
// truth simulator realizes it, `--effect` parses it, the candidate registry
// ranks it, gap-validate simulates, diagnoses and scores its files, all
// without any other change. The effect is a periodic accelerometer bias on
// x, A sin(2π t / 30 min) from switch-over, the same in every run (a design
// effect): no built-in effect has that signature, so a diagnosis that finds
// it found it through its registration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "lib/truth/effect.h"
#include "lib/units/units.h"
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/records/gap/validation/validation.h"

namespace insmc {
namespace {

constexpr double kPeriodS = 1800.0;

double periodic(double t_s) { return std::sin(2.0 * std::numbers::pi * t_s / kPeriodS); }

constexpr EffectParameter kParameters[] = {
    {"amplitude", Dimension::kAcceleration, 0.2 * kMgToMps2, "amplitude of the x accelerometer bias's 30-min wave",
     ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
};

const EffectDefinition kPeriodicBias{
    {"test_periodic_bias", "x accelerometer bias A sin(2π t / 30 min) from switch-over, the same in every run",
     kParameters, false, RawSensor::kAccelerometer},
    [](const EffectSpec& spec, const EffectContext& c, NormalDraws&, Perturbations& p) {
      const double a = spec.value("amplitude");
      std::vector<Vec3> nodes;
      for (double t = 0.0; t <= c.duration_s + c.noise_grid_s; t += c.noise_grid_s)
        nodes.push_back(Vec3(a * periodic(t), 0.0, 0.0));
      p.bias_process.add(GridProcess(c.noise_grid_s, std::move(nodes)));  // zero at switch-over: nothing to level
    }};

const EffectKind kPeriodicBiasKind = register_effect(kPeriodicBias);

gap::Candidate periodic_bias_candidate() {
  using namespace gap::candidates;
  return {"test_periodic_bias",
          "x accelerometer bias wave of 30 min, the same in every run",
          {amplitude("amplitude", Dimension::kAcceleration, 20 * kMgToMps2, "twenty times Table 3.1's 1 mg bias")},
          [](const gap::LayoutContext& ctx, std::span<const double> p) {
            runs::Extension e;
            e.mean = p[0] * signature_columns(ctx, "test_periodic_bias", 1, [](double t, runs::Columns3& a, runs::Columns3& th) {
                       th.setZero();
                       a.col(0) = Eigen::Vector3d(periodic(t), 0.0, 0.0);
                     }).col(0);
            return e;
          },
          {},
          "a test run longer than the wave's period"};
}

const bool kCandidateRegistered = [] {
  gap::register_candidate(periodic_bias_candidate());
  return true;
}();

TEST(TestOnlyEffect, TheRegistriesTakeItAfterTheBuiltInOnes) {
  ASSERT_TRUE(kCandidateRegistered);
  EXPECT_EQ(static_cast<std::size_t>(kPeriodicBiasKind.index()), effect_registry().size() - 1);
  EXPECT_EQ(parse_effect_kind("test_periodic_bias"), kPeriodicBiasKind);
  EXPECT_EQ(gap::candidate_registry().back().name, "test_periodic_bias");
  // Registering a name twice is refused, in both registries.
  EXPECT_THROW(register_effect(kPeriodicBias), std::logic_error);
  EXPECT_THROW(gap::register_candidate(periodic_bias_candidate()), std::logic_error);
}

TEST(TestOnlyEffect, TheTruthSimulatorRealizesItAndEffectArgumentsParseIt) {
  const EffectSpec spec = parse_effect("test_periodic_bias:amplitude=1mg");
  EXPECT_EQ(spec.kind, kPeriodicBiasKind);
  EXPECT_DOUBLE_EQ(spec.value("amplitude"), kMgToMps2);
  EXPECT_EQ(parse_effect(format_effect(spec)).values_si, spec.values_si);
  EffectContext context;
  context.duration_s = 3600.0;
  context.noise_grid_s = 10.0;
  const EffectSpec specs[] = {spec};
  const Perturbations p = realize_effects(specs, context);
  EXPECT_NEAR(p.bias_process.at(kPeriodS / 4).x(), kMgToMps2, 1e-12);
  EXPECT_NEAR(p.bias_process.at(3 * kPeriodS / 4).x(), -kMgToMps2, 1e-12);
  // Its records differ from the same runs without it: in the f rows only
  // through the bias, so the difference follows the wave.
  const RecordFile with = gap::own_layout_file({spec}, 7, 2), without = gap::own_layout_file({}, 7, 2);
  ASSERT_EQ(with.runs.size(), without.runs.size());
  double largest = 0;
  for (std::size_t r = 0; r < with.runs.size(); ++r)
    for (std::size_t i = 0; i < std::min(with.runs[r].rows.size(), without.runs[r].rows.size()); ++i)
      if (const RecordRow &a = with.runs[r].rows[i], &b = without.runs[r].rows[i]; a.f_mps2[0] && b.f_mps2[0])
        largest = std::max(largest, std::abs(*a.f_mps2[0] - *b.f_mps2[0]));
  EXPECT_GT(largest, 0.5 * kMgToMps2);
}

TEST(TestOnlyEffect, GapValidateSimulatesDiagnosesAndScoresItsFiles) {
  gap::ValidationOptions options;
  options.effects = {"test_periodic_bias"};
  options.magnitudes = {5.0};  // 1 mg
  options.seeds = 1;
  options.null_files = 0;
  options.runs_per_file = 12;
  const gap::ValidationResult result = gap::validate_diagnosis(options);
  ASSERT_EQ(result.cases.size(), 1u);
  const gap::ValidationCase& c = result.cases.front();
  EXPECT_EQ(c.effect, "test_periodic_bias");
  EXPECT_TRUE(c.significant) << c.gap << " p " << c.p_value;
  EXPECT_EQ(c.top, "test_periodic_bias");
  EXPECT_TRUE(c.identified);
  // The fitted amplitude is the wave's: its sign and size (a factor of two
  // either way tells a wave found from one absorbed by another candidate).
  EXPECT_GT(c.recovered_ratio, 0.5);
  EXPECT_LT(c.recovered_ratio, 2.0);
  std::printf("recovered amplitude / true: %.4f\n", c.recovered_ratio);
}

}  // namespace
}  // namespace insmc
