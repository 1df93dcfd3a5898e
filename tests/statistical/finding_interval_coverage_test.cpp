// Round trip of the diagnosis' finding (montecarlo/records/gap/ranking/finding_check.h,
// fit/subgrid.h): files simulated with an effect at a drawn strength,
// diagnosed blind; the first-ranked finding's 16–84 % range must cover the
// simulated value at its nominal rate, 68 %.
//
// Each file: 20 runs with one of five effects in turn, its parameter drawn
// log-uniform over a decade where it is detectable: velocity and angle
// random walk (their 1σ after an hour), a Gauss–Markov accelerometer bias
// instability (its σ, τ at its default 300 s), a thermal transient's bias
// at switch-on and its gyro drift at switch-on (the other two at their
// defaults: the drift 2 meru or the bias 0.1 mg, τ 1200 s); its own
// diagnosis seed. Every other file is written in conventions drawn by the
// layout fuzzer (gap/validation/writer_conventions.h: spacing, each run's own
// dropouts, resolution, pulses or not, short runs), the rest in insmc's own
// layout. Only the effect's own candidate is ranked: what is tested is the
// interval, not the identification (gap-validate's targets). The files are
// independent, so the number covered is binomial(m, 0.68) under the claim
// (m: files with a significant gap and a checked finding); two-sided
// acceptance region at α = 0.01, overall, per effect and parameter, and per
// layout. The thermal transient's bias and drift are each checked in every
// thermal file (the one not drawn at its default), its τ printed. Power
// companion, on the same diagnoses: the ranges halved about their values
// must fall below the region (a test that passed with them would not see
// intervals too narrow by two).
#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <iterator>
#include <map>
#include <random>
#include <tbb/parallel_for.h>

#include "lib/truth/effect.h"
#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/records/gap/validation/writer_conventions.h"
#include "montecarlo/records/gap/validation/validation.h"

namespace insmc::mc {
namespace {

constexpr int kFiles = 150;
constexpr std::uint64_t kSeed = 20261128;
constexpr double kNominal = 0.68;  // 16–84 %
constexpr double kAlpha = 0.01;

struct Drawn {
  std::string effect, parameter, unit;
  double low = 0, high = 0;  ///< the decade drawn over, in `unit`
};

const Drawn kDrawn[] = {{"velocity_random_walk", "velocity_1h", "mps", 0.15, 1.5},
                        {"angle_random_walk", "angle_1h", "mrad", 0.1, 1.0},
                        {"accel_bias_instability", "sigma", "ug", 50, 500},
                        {"thermal_transient", "bias", "mg", 0.1, 1.0},
                        {"thermal_transient", "drift", "meru", 2.0, 20.0}};
constexpr int kFamilies = static_cast<int>(std::size(kDrawn));

std::vector<gap::Candidate> only(const std::string& name) {
  for (const gap::Candidate& c : gap::candidate_registry())
    if (c.name == name) return {c};
  throw std::runtime_error("no candidate " + name);
}

/// One checked range: the parameter, its truth and the finding's estimate.
struct Checked {
  std::string label;  ///< effect.parameter
  double truth_si = 0;
  gap::ParameterEstimate estimate;
  bool fuzzed = false;
  bool drawn = false;  ///< the file's drawn parameter (one per file: independent across files)
};

bool covers(const gap::ParameterEstimate& e, double t) { return e.low <= t && t <= e.high; }
bool covers_halved(const gap::ParameterEstimate& e, double t) {
  return e.value - (e.value - e.low) / 2 <= t && t <= e.value + (e.high - e.value) / 2;
}

/// The acceptance region of binomial(m, kNominal) at kAlpha, two-sided.
std::pair<double, double> region(int m) {
  const boost::math::binomial claim(m, kNominal);
  return {boost::math::quantile(claim, kAlpha / 2), boost::math::quantile(boost::math::complement(claim, kAlpha / 2))};
}

TEST(FindingIntervalCoverage, TheFirstRankedRangeCoversTheSimulatedValueAtItsNominalRate) {
  struct File {
    const Drawn* drawn = nullptr;
    EffectSpec spec;
    bool fuzzed = false;
    std::vector<Checked> checked;
  };
  std::vector<File> files(kFiles);
  std::mt19937_64 draws(kSeed);  // the engine's sequence is fixed by the standard
  for (int f = 0; f < kFiles; ++f) {
    File& file = files[static_cast<std::size_t>(f)];
    file.drawn = &kDrawn[f % kFamilies];
    file.fuzzed = (f / kFamilies) % 2 == 1;
    const double u = static_cast<double>(draws() >> 11) * 0x1.0p-53;
    const double value = file.drawn->low * std::pow(file.drawn->high / file.drawn->low, u);
    file.spec = parse_effect(fmt::format("{}:{}={:.6g}{}", file.drawn->effect, file.drawn->parameter, value, file.drawn->unit));
  }
  tbb::parallel_for(0, kFiles, [&](int f) {
    File& file = files[static_cast<std::size_t>(f)];
    gap::DiagnosisOptions options;
    options.seed = kSeed + 1000 + static_cast<std::uint64_t>(f);
    options.max_selected = 1;
    options.null_shrink_files = 0;
    options.calibration_runs = 100;  // the null only decides which files are significant
    options.bootstrap = 500;
    options.candidates = std::make_shared<const std::vector<gap::Candidate>>(only(file.drawn->effect));
    const std::uint64_t seed = kSeed + static_cast<std::uint64_t>(f);
    const RecordFile records =
        file.fuzzed ? gap::file_in_conventions({file.spec}, seed, 20,
                                               gap::fuzzed_conventions_of(seed, file.spec.kind.info().needs_pulses, 900.0))
                    : gap::own_layout_file({file.spec}, seed, 20);
    const gap::Diagnosis g = gap::diagnose(records, options);
    if (!g.significant || g.first.ranking.empty()) return;
    const bool thermal = file.drawn->effect == "thermal_transient";
    for (const gap::ParameterEstimate& e : g.first.ranking[0].parameters) {
      const bool drawn = e.name == file.drawn->parameter;
      if (!drawn && !thermal) continue;
      file.checked.push_back({file.drawn->effect + "." + e.name, file.spec.value(e.name), e, file.fuzzed, drawn});
    }
  });
  int checked = 0, covered = 0, covered_halved = 0, at_grid_edge = 0;
  std::map<std::string, std::pair<int, int>> by_label, by_layout;  // checked, covered
  for (const File& file : files)
    for (const Checked& c : file.checked) {
      const bool in = covers(c.estimate, c.truth_si);
      std::printf("%s %s truth %.4g: %.4g [%.4g, %.4g]%s%s\n", file.fuzzed ? "fuzzed" : "own", c.label.c_str(),
                  c.truth_si, c.estimate.value, c.estimate.low, c.estimate.high, in ? "" : " (missed)",
                  c.estimate.at_grid_edge ? " (grid edge)" : "");
      // A drawn parameter is always checked; the thermal transient's other
      // two are claimed only off their grid's edges (the report marks one
      // at an edge and keeps its grid value).
      if (c.drawn) {
        ASSERT_TRUE(c.estimate.check.measured) << c.label;
      } else if (!c.estimate.check.measured) {
        ++at_grid_edge;
        continue;
      }
      auto& l = by_label[c.label];
      ++l.first, l.second += in;
      if (!c.drawn) continue;
      ++checked, covered += in, covered_halved += covers_halved(c.estimate, c.truth_si);
      auto& y = by_layout[c.fuzzed ? "fuzzed layouts" : "own layout"];
      ++y.first, y.second += in;
    }
  ASSERT_GE(checked, kFiles * 3 / 4) << "the drawn strengths are meant to be detectable";
  const auto [lo, hi] = region(checked);
  EXPECT_GE(covered, lo) << covered << " of " << checked << " covered";
  EXPECT_LE(covered, hi) << covered << " of " << checked << " covered";
  EXPECT_LT(covered_halved, lo) << "halved ranges: " << covered_halved << " of " << checked;
  std::printf("covered %d of %d (region %.0f-%.0f); halved %d; thermal parameters at a grid edge %d\n", covered, checked,
              lo, hi, covered_halved, at_grid_edge);
  // Each effect's parameter and each layout on its own too (its own
  // binomial region): one far off its rate is not hidden by the others.
  // Not claimed: the thermal transient's τ, whose range collapses where the
  // fits settle on a point of its search grid (600, 1200, 2400 s; the
  // default 1200 s is one): measured 27 of 54, ranges as narrow as ±0.1 %
  // (docs/gap-method.md §3, open). It is printed, not tested.
  for (const auto* groups : {&by_label, &by_layout})
    for (const auto& [name, counts] : *groups) {
      const auto [group_lo, group_hi] = region(counts.first);
      std::printf("  %s: %d of %d (region %.0f-%.0f)\n", name.c_str(), counts.second, counts.first, group_lo, group_hi);
      if (name == "thermal_transient.tau") continue;
      EXPECT_GE(counts.second, group_lo) << name;
      EXPECT_LE(counts.second, group_hi) << name;
    }
}

}  // namespace
}  // namespace insmc::mc
