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

#include "montecarlo/gap/model/run_analysis.h"

namespace insmc::gap {

/// Observations of different runs that are the same (quantity, axis, time),
/// numbered across layouts; the estimates follow, keyed by their x column.
class KeySpace {
 public:
  /// Numbers the rows of a layout (layouts are given once each, in order).
  void add_layout(const Layout& layout);
  int layouts() const { return static_cast<int>(row_keys_.size()); }
  /// Key of row i of layout L.
  int row_key(int layout, std::size_t row) const { return row_keys_[static_cast<std::size_t>(layout)][row]; }
  int row_key_count() const { return static_cast<int>(groups_.size()); }
  /// Key of the estimate of x column j.
  int estimate_key(int x_column) const { return row_key_count() + x_column; }
  int size() const { return row_key_count() + ux::kDim; }
  /// Coherent group of a key.
  int coherent_group(int key) const;

 private:
  std::vector<std::vector<int>> row_keys_;
  std::vector<int> groups_;                      // report group per row key
  std::vector<std::tuple<long long, int, int>> ids_;  // (t in µs, quantity, axis) per row key, sorted lookup below
  std::vector<int> order_;                       // row keys sorted by id
};

/// A run's normalized values (rows, then estimates: RunAnalyser::normalized)
/// placed in the key space (zero where the run has no such observation).
Eigen::VectorXd keyed_values(const Eigen::VectorXd& normalized, const RunAnalyser& analyser, int layout,
                             const KeySpace& keys);

using CoherentValues = std::array<double, kCoherentCount>;

struct RunSet {
  std::vector<GroupSums> sums;                       ///< per run
  std::array<Eigen::MatrixXd, kCoherentCount> gram;  ///< runs × runs per coherent group
  int size() const { return static_cast<int>(sums.size()); }
};

/// The set of runs whose keyed values are the columns of `keyed` (keys × runs).
RunSet make_run_set(std::vector<GroupSums> sums, const Eigen::MatrixXd& keyed, const KeySpace& keys);

/// A multiset of the runs pooled: the group sums added, and per coherent
/// group (1/m) Σ over pairs (a, b) of the multiset of the inner products,
/// i.e. m |mean of the runs' values|² over the group.
struct Pooled {
  GroupSums power;
  CoherentValues coherent{};
  int runs = 0;
};
Pooled pool(const RunSet& set, std::span<const int> runs);

}  // namespace insmc::gap
