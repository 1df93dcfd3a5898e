#include "montecarlo/records/runs/model/key_space.h"

#include <algorithm>
#include <cmath>

namespace insmc::runs {

void KeySpace::add_layout(const Layout& layout) {
  std::vector<int> keys(layout.rows.size());
  for (std::size_t i = 0; i < layout.rows.size(); ++i) {
    const ObservationRow& row = layout.rows[i];
    const std::tuple<long long, int, int> id{std::llround(row.t_s * 1e6), static_cast<int>(row.quantity), row.axis};
    const auto it = std::lower_bound(order_.begin(), order_.end(), id,
                                     [&](int k, const auto& v) { return ids_[static_cast<std::size_t>(k)] < v; });
    if (it != order_.end() && ids_[static_cast<std::size_t>(*it)] == id) {
      keys[i] = *it;
      continue;
    }
    const int key = static_cast<int>(groups_.size());
    groups_.push_back(row.group);
    ids_.push_back(id);
    order_.insert(it, key);
    keys[i] = key;
  }
  row_keys_.push_back(std::move(keys));
}

int KeySpace::coherent_group(int key) const {
  return key < row_key_count() ? coherent_group_of(groups_[static_cast<std::size_t>(key)])
                               : coherent_group_of(kEstimatesGroup);
}

Eigen::VectorXd keyed_values(const Eigen::VectorXd& v, const RunAnalyser& a, int layout, const KeySpace& keys) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(keys.size());
  const std::size_t rows = v.size() - a.estimate_x_columns().size();
  for (std::size_t i = 0; i < rows; ++i) out[keys.row_key(layout, i)] = v[static_cast<Eigen::Index>(i)];
  for (std::size_t k = 0; k < a.estimate_x_columns().size(); ++k)
    out[keys.estimate_key(a.estimate_x_columns()[k])] = v[static_cast<Eigen::Index>(rows + k)];
  return out;
}

}  // namespace insmc::runs
