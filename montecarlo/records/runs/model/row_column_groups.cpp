#include "montecarlo/records/runs/model/row_column_groups.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>

#include "lib/common/assert.h"
#include "montecarlo/records/runs/model/quadratic_forms.h"

namespace insmc::runs {

namespace {

using Pattern = std::vector<std::uint64_t>;

/// A group joins at most this many patterns next to each other in the
/// patterns' order (bounds the search: patterns × this many unions).
constexpr std::size_t kMaxPatternsPerGroup = 64;

double group_cost(double rows, std::size_t columns) {
  return (rows + kGroupOverheadRows) * static_cast<double>(columns) * static_cast<double>(columns);
}

std::size_t columns_in(const Pattern& p) {
  std::size_t n = 0;
  for (std::uint64_t w : p) n += static_cast<std::size_t>(std::popcount(w));
  return n;
}

void join(Pattern& into, const Pattern& p) {
  for (std::size_t w = 0; w < p.size(); ++w) into[w] |= p[w];
}

}  // namespace

RowColumnGroups group_rows_by_columns(const Eigen::MatrixXd& a, Eigen::Index d) {
  INSMC_ASSERT(d >= 0 && d <= a.cols(), "{} columns of a {}-column matrix", d, a.cols());
  const auto words = static_cast<std::size_t>((d + 63) / 64);
  // Column c is bit 63 − c mod 64 of word c / 64, so that the map orders the
  // patterns as read from column 0: patterns that differ only in late
  // columns (a random process' knots) lie next to each other.
  std::map<Pattern, std::vector<Eigen::Index>> rows_of_pattern;
  Pattern pattern(words);
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    std::fill(pattern.begin(), pattern.end(), 0);
    for (Eigen::Index c = 0; c < d; ++c)
      if (a(i, c) != 0.0) pattern[static_cast<std::size_t>(c / 64)] |= std::uint64_t{1} << (63 - c % 64);
    rows_of_pattern[pattern].push_back(i);
  }
  std::vector<const Pattern*> patterns;
  std::vector<const std::vector<Eigen::Index>*> members;
  for (const auto& [p, rows] : rows_of_pattern) patterns.push_back(&p), members.push_back(&rows);
  // The least cost of the first j patterns in groups of consecutive ones
  // (best[j]), the last group starting at pattern from[j].
  const std::size_t P = patterns.size();
  std::vector<double> best(P + 1, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> from(P + 1, 0);
  best[0] = 0.0;
  Pattern joined(words);
  for (std::size_t j = 1; j <= P; ++j) {
    std::fill(joined.begin(), joined.end(), 0);
    double rows = 0.0;
    for (std::size_t i = j; i-- > 0 && j - i <= kMaxPatternsPerGroup;) {
      join(joined, *patterns[i]);
      rows += static_cast<double>(members[i]->size());
      const double cost = best[i] + group_cost(rows, columns_in(joined));
      if (cost < best[j]) best[j] = cost, from[j] = i;
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> spans;  // [first, last) patterns of each group
  Pattern every(words);
  for (const Pattern* p : patterns) join(every, *p);
  if (P > 0 && group_cost(static_cast<double>(a.rows()), columns_in(every)) < best[P]) {
    spans.emplace_back(0, P);
  } else {
    for (std::size_t j = P; j > 0; j = from[j]) spans.emplace_back(from[j], j);
    std::reverse(spans.begin(), spans.end());
  }
  RowColumnGroups g;
  for (const auto& [first, last] : spans) {
    std::vector<Eigen::Index>& rows = g.rows.emplace_back();
    std::fill(joined.begin(), joined.end(), 0);
    for (std::size_t k = first; k < last; ++k) {
      join(joined, *patterns[k]);
      rows.insert(rows.end(), members[k]->begin(), members[k]->end());
    }
    std::sort(rows.begin(), rows.end());
    std::vector<Eigen::Index>& cols = g.columns.emplace_back();
    for (Eigen::Index c = 0; c < d; ++c)
      if (joined[static_cast<std::size_t>(c / 64)] >> (63 - c % 64) & 1) cols.push_back(c);
  }
  return g;
}

double grouped_forms_cost(const RowColumnGroups& groups) {
  double cost = 0.0;
  for (std::size_t k = 0; k < groups.rows.size(); ++k)
    cost += group_cost(static_cast<double>(groups.rows[k].size()), groups.columns[k].size());
  return cost;
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
