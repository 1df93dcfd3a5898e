#include "montecarlo/records/gap/ranking/finding_check.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "lib/truth/effect.h"
#include "montecarlo/records/gap/fit/subgrid.h"
#include "montecarlo/records/gap/ranking/effect_terms.h"

namespace insmc::gap {
namespace {

/// Run indices of the simulated runs start here, far past any null run's.
constexpr std::uint64_t kFirstRun = std::uint64_t{1} << 40;

const Candidate* candidate_named(const DiagnosisOptions& options, const std::string& name) {
  for (const Candidate& c : candidates_of(options))
    if (c.name == name) return &c;
  return nullptr;
}

/// The simulated value of parameter `name`, when the effect has one.
bool simulated_value(const EffectSpec& spec, const std::string& name, double& value) {
  const EffectInfo& info = effect_info(spec.kind);
  for (std::size_t i = 0; i < info.parameters.size(); ++i)
    if (info.parameters[i].name == name) return value = spec.values_si[i], true;
  return false;
}

SimulatedCheck measure(double simulated, const std::vector<double>& fitted) {
  SimulatedCheck c;
  c.measured = true;
  c.files = static_cast<int>(fitted.size());
  c.simulated = simulated;
  c.logarithmic = simulated > 0 && std::all_of(fitted.begin(), fitted.end(), [](double v) { return v > 0; });
  std::vector<double> d;
  for (double v : fitted) d.push_back(c.logarithmic ? std::log(v / simulated) : v - simulated);
  c.bias = std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
  double ss = 0;
  for (double x : d) ss += (x - c.bias) * (x - c.bias);
  c.spread = d.size() > 1 ? std::sqrt(ss / static_cast<double>(d.size() - 1)) : 0.0;
  return c;
}

}  // namespace

ParameterEstimate corrected(const ParameterEstimate& e, const SimulatedCheck& check) {
  ParameterEstimate out = e;
  out.check = check;
  const bool logarithmic = check.logarithmic && e.value > 0 && e.low > 0 && e.high > 0;
  if (check.logarithmic && !logarithmic) return out;  // a range reaching 0 or below: the ratio does not apply
  const auto to = [&](double v) { return logarithmic ? std::log(v) : v; };
  const auto from = [&](double t) { return logarithmic ? std::exp(t) : t; };
  const double se = check.files > 0 ? check.spread / std::sqrt(static_cast<double>(check.files)) : 0.0;
  const double centre = to(e.value) - check.bias;
  const double below = std::hypot(to(e.value) - to(e.low), se), above = std::hypot(to(e.high) - to(e.value), se);
  out.value = from(centre);
  out.low = from(centre - below);
  out.high = from(centre + above);
  return out;
}

std::optional<CandidateResult> check_finding(const CandidateResult& first, const runs::PreparedRuns& p,
                                             const RecordFile& file, const ModelNull& null,
                                             const DiagnosisOptions& options) {
  if (first.as_effect.empty()) return std::nullopt;
  const Candidate* c = candidate_named(options, first.effect);
  if (c == nullptr) return std::nullopt;
  CandidateResult finding = first;
  const EffectSpec spec = parse_effect(finding.as_effect, "as_effect");
  // Only a parameter off its grid's edges and of the effect's own is corrected.
  const auto checkable = [&](const ParameterEstimate& e) {
    double simulated = 0;
    return !e.at_grid_edge && simulated_value(spec, e.name, simulated);
  };
  if (std::none_of(finding.parameters.begin(), finding.parameters.end(), checkable)) return std::nullopt;
  const std::size_t n = p.runs.size();
  runs::PreparedRuns q = p;
  std::vector<int> layout_of;
  q.runs = simulate_like_records(q, file, options, static_cast<int>(n) * kFindingCheckFiles, kFirstRun, {spec},
                                 layout_of);
  q.layout_of = layout_of;
  std::vector<std::vector<int>> files(kFindingCheckFiles);
  for (std::size_t f = 0; f < files.size(); ++f) {
    files[f].resize(n);
    std::iota(files[f].begin(), files[f].end(), static_cast<int>(f * n));
  }
  const NullCalibration& m0 = null.calibration;
  const CandidateSums sums = evaluate_candidate(q, *c, std::vector<std::vector<runs::Extension>>(q.lattices.size()), m0, files);
  std::vector<std::vector<double>> fitted(c->parameters.size());
  for (const std::vector<int>& runs : files) {
    const RunsUnderChoice under(sums, runs);
    std::vector<double> theta = subgrid_values(*c, under, choose(under, m0), m0);
    if (c->to_effect_terms) c->to_effect_terms(theta, q.site);
    for (std::size_t i = 0; i < theta.size(); ++i) fitted[i].push_back(theta[i]);
  }
  for (std::size_t i = 0; i < finding.parameters.size(); ++i) {
    ParameterEstimate& e = finding.parameters[i];
    double simulated = 0;
    if (!checkable(e) || !simulated_value(spec, e.name, simulated)) continue;
    e = corrected(e, measure(simulated, fitted[i]));
  }
  const EffectArgument a = effect_argument(finding, p.site);
  finding.as_effect = a.text;
  finding.as_effect_kept = a.kept;
  return finding;
}

}  // namespace insmc::gap
