#include "montecarlo/records/gap/metric/run_set.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "lib/common/assert.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

RunSet make_run_set(std::vector<runs::GroupSums> sums, const Eigen::MatrixXd& keyed, const runs::KeySpace& keys) {
  INSMC_ASSERT(keyed.cols() == static_cast<Eigen::Index>(sums.size()) && keyed.rows() == keys.size(),
               "keyed values {}x{} for {} runs, {} keys", keyed.rows(), keyed.cols(), sums.size(), keys.size());
  RunSet set;
  set.sums = std::move(sums);
  std::array<std::vector<Eigen::Index>, runs::kCoherentCount> members;
  for (int k = 0; k < keys.size(); ++k) members[static_cast<std::size_t>(keys.coherent_group(k))].push_back(k);
  for (int c = 0; c < runs::kCoherentCount; ++c) {
    Eigen::MatrixXd z = keyed(members[static_cast<std::size_t>(c)], Eigen::all);
    if (set.size() <= kMaxGramRuns)
      set.gram[static_cast<std::size_t>(c)] = z.transpose() * z;
    else
      set.values[static_cast<std::size_t>(c)] = std::move(z);
  }
  return set;
}

double RunSet::pair_sum(int c, std::span<const int> runs) const {
  const Eigen::MatrixXd& g = gram[static_cast<std::size_t>(c)];
  double sum = 0.0;
  if (size() <= kMaxGramRuns) {
    for (int a : runs)
      for (int b : runs) sum += g(a, b);
    return sum;
  }
  const Eigen::MatrixXd& z = values[static_cast<std::size_t>(c)];
  Eigen::VectorXd total = Eigen::VectorXd::Zero(z.rows());
  for (int a : runs) total += z.col(a);
  return total.squaredNorm();
}

double RunSet::distinct_pair_sum(int c) const {
  if (size() <= kMaxGramRuns) {
    const Eigen::MatrixXd& g = gram[static_cast<std::size_t>(c)];
    return g.sum() - g.trace();
  }
  // |Σ z|² − Σ |z_a|²: the pairs of one run with itself taken off.
  const Eigen::MatrixXd& z = values[static_cast<std::size_t>(c)];
  return z.rowwise().sum().squaredNorm() - z.colwise().squaredNorm().sum();
}

Pooled pool(const RunSet& set, std::span<const int> runs) {
  Pooled p;
  p.runs = static_cast<int>(runs.size());
  for (int r : runs) p.power += set.sums[static_cast<std::size_t>(r)];
  if (runs.empty()) return p;
  for (int c = 0; c < runs::kCoherentCount; ++c)
    p.coherent[static_cast<std::size_t>(c)] = set.pair_sum(c, runs) / static_cast<double>(runs.size());
  return p;
}

namespace {

void evaluate_run(EvaluatedRuns& e, std::size_t r, const runs::RunData& run, int layout, const runs::RunAnalyser& a,
                  const runs::KeySpace& keys) {
  const Eigen::VectorXd v = a.normalized(run_values(run));
  e.sums[r] = a.sums_of(v);
  e.keyed.col(static_cast<Eigen::Index>(r)) = runs::keyed_values(v, a, layout, keys);
}

EvaluatedRuns sized_for(std::size_t runs, const runs::KeySpace& keys) {
  EvaluatedRuns e;
  e.sums.resize(runs);
  e.keyed.resize(keys.size(), static_cast<Eigen::Index>(runs));
  return e;
}

}  // namespace

EvaluatedRuns evaluate_runs(const std::vector<runs::RunData>& runs, const std::vector<int>& layout_of,
                        const std::vector<const runs::RunAnalyser*>& analysers, const runs::KeySpace& keys) {
  EvaluatedRuns e = sized_for(runs.size(), keys);
  for (std::size_t r = 0; r < runs.size(); ++r)
    evaluate_run(e, r, runs[r], layout_of[r], *analysers[static_cast<std::size_t>(layout_of[r])], keys);
  return e;
}

EvaluatedRuns evaluate_runs(const runs::PreparedRuns& p, const std::vector<std::vector<const runs::Extension*>>& extensions,
                            const std::vector<bool>& used) {
  const runs::PreparedRuns* parts[] = {&p};
  return std::move(evaluate_runs(parts, extensions, used).front());
}

std::vector<EvaluatedRuns> evaluate_runs(std::span<const runs::PreparedRuns* const> parts,
                                         const std::vector<std::vector<const runs::Extension*>>& extensions,
                                         const std::vector<bool>& used) {
  const runs::PreparedRuns& first = *parts.front();
  std::vector<std::vector<std::vector<std::size_t>>> runs_of(parts.size());
  std::vector<EvaluatedRuns> e;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const runs::PreparedRuns& p = *parts[i];
    INSMC_ASSERT(p.layouts.size() == first.layouts.size(), "parts of {} and {} layouts", p.layouts.size(),
                 first.layouts.size());
    runs_of[i].resize(p.layouts.size());
    for (std::size_t r = 0; r < p.runs.size(); ++r) runs_of[i][static_cast<std::size_t>(p.layout_of[r])].push_back(r);
    e.push_back(sized_for(p.runs.size(), p.keys));
  }
  runs::for_each_layout_analyser(first, extensions, used, [&](std::size_t L, runs::RunAnalyser&& a) {
    for (std::size_t i = 0; i < parts.size(); ++i)
      for (std::size_t r : runs_of[i][L]) evaluate_run(e[i], r, parts[i]->runs[r], static_cast<int>(L), a, parts[i]->keys);
  });
  return e;
}

}  // namespace insmc::gap
