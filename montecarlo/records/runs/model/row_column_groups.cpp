#include "montecarlo/records/runs/model/row_column_groups.h"

#include <cstdint>
#include <map>
#include <numeric>

#include "lib/common/assert.h"
#include "montecarlo/records/runs/model/quadratic_forms.h"

namespace insmc::runs {

RowColumnGroups group_rows_by_columns(const Eigen::MatrixXd& a, Eigen::Index d) {
  INSMC_ASSERT(d >= 0 && d <= a.cols(), "{} columns of a {}-column matrix", d, a.cols());
  const auto words = static_cast<std::size_t>((d + 63) / 64);
  std::map<std::vector<std::uint64_t>, std::size_t> group_of;
  RowColumnGroups g;
  std::vector<std::uint64_t> pattern(words);
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    std::fill(pattern.begin(), pattern.end(), 0);
    for (Eigen::Index c = 0; c < d; ++c)
      if (a(i, c) != 0.0) pattern[static_cast<std::size_t>(c / 64)] |= std::uint64_t{1} << (c % 64);
    const auto [it, added] = group_of.try_emplace(pattern, g.rows.size());
    if (added) {
      if (g.rows.size() == kMaxColumnGroups) {
        // Too many patterns: every row over every column.
        RowColumnGroups all;
        all.rows.emplace_back(static_cast<std::size_t>(a.rows()));
        std::iota(all.rows[0].begin(), all.rows[0].end(), Eigen::Index{0});
        all.columns.emplace_back(static_cast<std::size_t>(d));
        std::iota(all.columns[0].begin(), all.columns[0].end(), Eigen::Index{0});
        return all;
      }
      g.rows.emplace_back();
      std::vector<Eigen::Index>& cols = g.columns.emplace_back();
      for (Eigen::Index c = 0; c < d; ++c)
        if (pattern[static_cast<std::size_t>(c / 64)] >> (c % 64) & 1) cols.push_back(c);
    }
    g.rows[it->second].push_back(i);
  }
  return g;
}

std::vector<Eigen::MatrixXd> group_blocks(const Eigen::MatrixXd& a, const RowColumnGroups& groups,
                                          std::span<const Eigen::Index> source_rows,
                                          const Eigen::VectorXd& column_scale) {
  std::vector<Eigen::MatrixXd> blocks(groups.rows.size());
  for (std::size_t k = 0; k < groups.rows.size(); ++k) {
    const std::vector<Eigen::Index>& rows = groups.rows[k];
    const std::vector<Eigen::Index>& cols = groups.columns[k];
    Eigen::MatrixXd& b = blocks[k];
    b.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
    for (std::size_t j = 0; j < cols.size(); ++j) {
      const Eigen::Index c = cols[j];
      INSMC_ASSERT(c < a.cols(), "column {} of a {}-column matrix", c, a.cols());
      const double* from = a.col(c).data();
      double* to = b.col(static_cast<Eigen::Index>(j)).data();
      const double scale = column_scale.size() > 0 ? column_scale[c] : 1.0;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const Eigen::Index i = source_rows.empty() ? rows[r] : source_rows[static_cast<std::size_t>(rows[r])];
        to[r] = from[i] * scale;
      }
    }
  }
  return blocks;
}

Eigen::VectorXd grouped_row_quadratic_forms(const std::vector<Eigen::MatrixXd>& blocks, const Eigen::MatrixXd& m,
                                            const RowColumnGroups& groups, Eigen::Index rows) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(rows);
  Eigen::MatrixXd m_group;
  Eigen::VectorXd q_group;
  for (std::size_t k = 0; k < groups.rows.size(); ++k) {
    const std::vector<Eigen::Index>& cols = groups.columns[k];
    const Eigen::MatrixXd& b = blocks[k];
    if (b.rows() == 0 || cols.empty()) continue;  // rows that see none of the columns: 0
    INSMC_ASSERT(cols.back() < m.rows(), "column {} of a {}-cause form", cols.back(), m.rows());
    m_group = m(cols, cols);
    q_group.resize(b.rows());
    row_quadratic_forms(b.data(), static_cast<std::size_t>(b.outerStride()), static_cast<std::size_t>(b.rows()),
                        cols.size(), m_group.data(), static_cast<std::size_t>(m_group.outerStride()), q_group.data());
    for (Eigen::Index r = 0; r < b.rows(); ++r) q[groups.rows[k][static_cast<std::size_t>(r)]] = q_group[r];
  }
  return q;
}

}  // namespace insmc::runs
