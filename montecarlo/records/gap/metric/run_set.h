#pragma once
/// A set of runs under one model as the gap metric sees it (gap_metric.h):
/// per run its group sums (the scatter of each run), and per coherent group
/// the inner products of every pair of runs over the observations they
/// share (what the runs have in common). Any multiset of the runs (a
/// training half, a bootstrap file) is then pooled without going back to
/// the rows.
#include <Eigen/Core>
#include <array>
#include <span>
#include <tuple>
#include <vector>

#include "montecarlo/records/runs/model/key_space.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "montecarlo/records/runs/files/layout.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

using CoherentValues = std::array<double, runs::kCoherentCount>;

/// Up to this many runs a set keeps every pair's inner products (13 ×
/// runs² doubles: 6.8 MB at 256), which pools a multiset of m runs in m²
/// look-ups; a larger set (a null calibration of thousands of runs) keeps
/// the runs' keyed values instead and pools by adding their columns, so its
/// memory and the time to build it grow with the runs, not their square.
inline constexpr int kMaxGramRuns = 256;

struct RunSet {
  std::vector<runs::GroupSums> sums;                       ///< per run
  std::array<Eigen::MatrixXd, runs::kCoherentCount> gram;  ///< runs × runs per coherent group (≤ kMaxGramRuns runs)
  std::array<Eigen::MatrixXd, runs::kCoherentCount> values;  ///< the group's keys × runs (more runs)
  int size() const { return static_cast<int>(sums.size()); }
  /// Σ over ordered pairs (a, b) of `runs` (a multiset) of the inner
  /// products over coherent group c: |Σ_a z_a|².
  double pair_sum(int c, std::span<const int> runs) const;
  /// The same over every pair of different runs of the set (a ≠ b).
  double distinct_pair_sum(int c) const;
};

/// The set of runs whose keyed values are the columns of `keyed` (keys × runs).
RunSet make_run_set(std::vector<runs::GroupSums> sums, const Eigen::MatrixXd& keyed, const runs::KeySpace& keys);

/// Runs under one model: each run's group sums and its normalized values in
/// the key space (columns).
struct EvaluatedRuns {
  std::vector<runs::GroupSums> sums;
  Eigen::MatrixXd keyed;  ///< keys × runs
  RunSet set(const runs::KeySpace& keys) const { return make_run_set(sums, keyed, keys); }
};

/// `runs` (with their layouts) under the analysers of each layout.
EvaluatedRuns evaluate_runs(const std::vector<runs::RunData>& runs, const std::vector<int>& layout_of,
                        const std::vector<const runs::RunAnalyser*>& analysers, const runs::KeySpace& keys);

/// The runs of `p` under the models of their layouts with `extensions`
/// (per lattice; runs::layout_analysers), each layout's model built, used
/// for its runs and dropped before the next: the memory of one model, not
/// of one per layout. `used`: the layouts some run of `p` has.
EvaluatedRuns evaluate_runs(const runs::PreparedRuns& p, const std::vector<std::vector<const runs::Extension*>>& extensions,
                            const std::vector<bool>& used);
/// The same for several sets of runs on the same layouts (the records and
/// null files simulated in their layouts): each layout's model built once
/// for all of them; each set's runs evaluated as they would be alone.
std::vector<EvaluatedRuns> evaluate_runs(std::span<const runs::PreparedRuns* const> parts,
                                         const std::vector<std::vector<const runs::Extension*>>& extensions,
                                         const std::vector<bool>& used);

/// A multiset of the runs pooled: the group sums added, and per coherent
/// group (1/m) Σ over pairs (a, b) of the multiset of the inner products,
/// i.e. m |mean of the runs' values|² over the group.
struct Pooled {
  runs::GroupSums power;
  CoherentValues coherent{};
  int runs = 0;
};
Pooled pool(const RunSet& set, std::span<const int> runs);

}  // namespace insmc::gap
