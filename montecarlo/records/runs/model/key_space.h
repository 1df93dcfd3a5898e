#pragma once
/// The observations of runs on different layouts numbered as one space, so
/// that runs can be compared key by key (what they have in common).
#include <Eigen/Core>
#include <tuple>
#include <vector>

#include "montecarlo/records/runs/model/run_analysis.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::runs {

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
  int size() const { return row_key_count() + uncertainty_slot::kDim; }
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

}  // namespace insmc::runs
