// The named-effect registry: names, parameters, parsing with units, errors
// naming the field, format/parse round trip, streams, and the random
// processes effects are built from.
#include "lib/truth/effect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "lib/common/input_error.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

TEST(EffectRegistry, ListsEveryEffectOfIssue6OnceInKindOrder) {
  const std::set<std::string> required = {
      "quantization",     "sway",           "accel_bias_instability", "gyro_drift_instability",
      "angle_random_walk", "velocity_random_walk", "thermal_transient", "anisoelastic_drift",
      "scale_factor_nonlinearity", "gravity_model", "deflection_of_vertical", "alignment_transient",
      "switch_transient"};
  std::set<std::string> names;
  for (std::size_t k = 0; k < effect_registry().size(); ++k) {
    const EffectInfo& e = effect_registry()[k];
    const EffectKind kind(static_cast<int>(k));
    EXPECT_EQ(&kind.info(), &e);
    EXPECT_TRUE(names.insert(std::string(e.name)).second) << e.name;
    EXPECT_FALSE(e.description.empty()) << e.name;
    EXPECT_LE(e.parameters.size(), static_cast<std::size_t>(kMaxEffectParameters));
    std::set<std::string> params;
    for (const EffectParameter& p : e.parameters) {
      EXPECT_TRUE(params.insert(std::string(p.name)).second) << e.name << "." << p.name;
      EXPECT_FALSE(p.description.empty()) << e.name << "." << p.name;
    }
    EXPECT_NO_THROW(validate_effect(default_effect(kind))) << e.name;  // defaults are valid
    EXPECT_EQ(parse_effect_kind(e.name), kind);
  }
  EXPECT_EQ(names, required);
}

TEST(EffectParsing, NameAloneTakesTheDefaults) {
  const EffectSpec s = parse_effect("accel_bias_instability");
  EXPECT_EQ(to_string(s.kind), "accel_bias_instability");
  EXPECT_DOUBLE_EQ(s.value("sigma"), 50e-6 * kGravityMps2);
  EXPECT_DOUBLE_EQ(s.value("tau"), 300.0);
}

TEST(EffectParsing, ParametersCarryUnits) {
  const EffectSpec s = parse_effect("accel_bias_instability:sigma=5e-5mps2,tau=10min");
  EXPECT_DOUBLE_EQ(s.value("sigma"), 5e-5);
  EXPECT_DOUBLE_EQ(s.value("tau"), 600.0);
  const EffectSpec g = parse_effect(" gyro_drift_instability : tau = 0s , sigma = 0.5meru ");
  EXPECT_DOUBLE_EQ(g.value("sigma"), 0.5 * kMeruToRadps);
  EXPECT_DOUBLE_EQ(g.value("tau"), 0.0);
  EXPECT_DOUBLE_EQ(parse_effect("quantization:dv_pulse=1ftps").value("dv_pulse"), kFtpsToMps);
  EXPECT_DOUBLE_EQ(parse_effect("deflection_of_vertical:xi=-20arcsec").value("xi"), -20 * kArcsecToRad);
  EXPECT_DOUBLE_EQ(parse_effect("gravity_model:j2=1e-5").value("j2"), 1e-5);
}

/// The InputError of parsing `text`, whose field must contain `field_part`.
void expect_input_error(const std::string& text, const std::string& field_part) {
  try {
    parse_effect(text, "--effect");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(field_part), std::string::npos) << text << " -> " << e.what();
    EXPECT_NE(std::string(e.what()).find("--effect"), std::string::npos) << e.what();
  }
}

TEST(EffectParsing, BadInputNamesTheField) {
  expect_input_error("wobble", "unknown effect");
  expect_input_error("sway:accel_rms", "sway");                       // no '='
  expect_input_error("sway:speed=1mps", "sway.speed");                // unknown parameter
  expect_input_error("sway:accel_rms=0.1", "sway.accel_rms");         // unit missing
  expect_input_error("sway:accel_rms=0.1m", "sway.accel_rms");        // wrong unit
  expect_input_error("sway:accel_rms=-1mg", "sway.accel_rms");        // negative
  expect_input_error("sway:period_min=0s", "sway.period_min");        // must be > 0
  expect_input_error("sway:period_min=30s", "sway.period_min");       // > period_max
  expect_input_error("sway:components=2.5", "sway.components");
  expect_input_error("thermal_transient:tau=1s,tau=2s", "thermal_transient.tau");  // twice
  expect_input_error("quantization:dv_pulse=0mps", "quantization.dv_pulse");
  expect_input_error("accel_bias_instability:sigma=nanmg", "accel_bias_instability.sigma");
  expect_input_error("accel_bias_instability:", "accel_bias_instability");
}

TEST(EffectParsing, FormatParsesBackToTheSameSpec) {
  for (std::size_t k = 0; k < effect_registry().size(); ++k) {
    const EffectInfo& e = effect_registry()[k];
    EffectSpec s = default_effect(EffectKind(static_cast<int>(k)));
    for (std::size_t i = 0; i < e.parameters.size(); ++i) s.values_si[i] *= 1.37;  // not a round value
    if (e.name == "sway") s = parse_effect("sway:components=3,period_max=30s");
    const std::string text = format_effect(s);
    const EffectSpec back = parse_effect(text);
    EXPECT_EQ(back.kind, s.kind) << text;
    for (std::size_t i = 0; i < e.parameters.size(); ++i)
      EXPECT_NEAR(back.values_si[i], s.values_si[i], 1e-11 * std::abs(s.values_si[i])) << text;
  }
}

TEST(EffectStreams, AreDistinctPerKindAndOccurrence) {
  std::set<std::uint64_t> streams;
  for (std::size_t k = 0; k < effect_registry().size(); ++k)
    for (int n = 0; n < 4; ++n) EXPECT_TRUE(streams.insert(effect_stream(EffectKind(static_cast<int>(k)), n)).second);
  EXPECT_EQ(streams.count(0), 0u);  // stream 0 is left to callers' own draws
}

TEST(EffectRealization, IsDeterministicAndIndependentOfOtherEffects) {
  const NormalSource noise = hashed_normal_source(7);
  EffectContext c;
  c.duration_s = 600.0;
  c.noise = &noise;
  const std::vector<EffectSpec> one = {parse_effect("switch_transient")};
  const std::vector<EffectSpec> two = {parse_effect("sway"), parse_effect("switch_transient")};
  const Perturbations a = realize_effects(one, c), b = realize_effects(one, c), d = realize_effects(two, c);
  EXPECT_EQ(a.misalignment_step_rad, b.misalignment_step_rad);
  EXPECT_EQ(a.misalignment_step_rad, d.misalignment_step_rad);  // sway draws from its own stream
  EXPECT_EQ(a.nav_bias_step_mps2, d.nav_bias_step_mps2);
  EXPECT_NE(a.misalignment_step_rad, Vec3::Zero());
  // A repeated kind draws anew.
  const std::vector<EffectSpec> twice = {parse_effect("switch_transient"), parse_effect("switch_transient")};
  const Perturbations t = realize_effects(twice, c);
  EXPECT_GT((t.misalignment_step_rad - 2.0 * a.misalignment_step_rad).norm(), 1e-6);
}

TEST(GridProcess, IntegralsAreExactForThePiecewiseLinearForm) {
  // Nodes 0, 1, 3, 2 at Δ = 2 s: check against sums of trapezoids/Simpson by hand.
  const GridProcess p(2.0, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(2, 0, 0)});
  EXPECT_DOUBLE_EQ(p.at(1.0).x(), 0.5);
  EXPECT_DOUBLE_EQ(p.at(5.0).x(), 2.5);
  EXPECT_DOUBLE_EQ(p.at(100.0).x(), 2.0);  // constant after the last node
  // ∫_1^5 p = ∫_1^2 (s/2) + ∫_2^4 (1 + (s−2)) + ∫_4^5 (3 − (s−4)/2) = 0.75 + 4 + 2.75.
  const GridProcess::Integrals i = p.integrals(1.0, 5.0);
  EXPECT_NEAR(i.first.x(), 7.5, 1e-12);
  // By hand, segment by segment ([1,2]: p = s/2; [2,4]: s − 1; [4,5]: 5 − s/2):
  // ∫ (5 − s) p = 31/12 + 22/3 + 17/12 = 34/3; ∫ (5 − s)²/2 p = 215/48 + 22/3 + 23/48 = 295/24.
  EXPECT_NEAR(i.second.x(), 34.0 / 3.0, 1e-12);
  EXPECT_NEAR(i.third.x(), 295.0 / 24.0, 1e-12);
}

TEST(GridProcess, GaussMarkovHasItsSigmaAndCorrelationTime) {
  // Stationary first-order Gauss–Markov: variance σ², autocorrelation e^{−lag/τ}.
  const NormalSource noise = hashed_normal_source(11);
  NormalDraws draws(noise, 1);
  const double sigma = 2.0, tau = 50.0, grid = 5.0;
  const GridProcess p = make_gauss_markov(sigma, tau, 400000.0, grid, draws);
  const auto& v = p.nodes();
  double var = 0.0, lag_tau = 0.0;
  const std::size_t lag = 10, n = v.size() - lag;  // 10 nodes = τ
  for (std::size_t k = 0; k < n; ++k) {
    var += v[k].squaredNorm() / 3.0;
    lag_tau += v[k].dot(v[k + lag]) / 3.0;
  }
  var /= n;
  lag_tau /= n;
  // ~8000 correlation times × 3 axes: relative standard errors ~1%.
  EXPECT_NEAR(std::sqrt(var), sigma, 0.03 * sigma);
  EXPECT_NEAR(lag_tau / var, std::exp(-1.0), 0.03);
}

TEST(GridProcess, RandomWalkReachesSigmaAfterOneHour) {
  const NormalSource noise = hashed_normal_source(12);
  double sum2 = 0.0;
  const int runs = 400;
  for (int r = 0; r < runs; ++r) {
    NormalDraws draws(noise, 100 + r);
    const GridProcess p = make_random_walk(3.0, 3600.0, 10.0, draws);
    sum2 += p.at(3600.0).squaredNorm() / 3.0;
  }
  // 1200 samples of a χ²: relative standard error of σ̂ ≈ 2%.
  EXPECT_NEAR(std::sqrt(sum2 / runs), 3.0, 0.2);
}

}  // namespace
}  // namespace insmc
