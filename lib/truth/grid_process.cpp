#include "lib/truth/grid_process.h"

#include <algorithm>
#include <cmath>

#include "lib/common/assert.h"

namespace insmc {

GridProcess::GridProcess(double grid_s, std::vector<Vec3> nodes)
    : grid_s_(grid_s), nodes_(std::move(nodes)) {
  INSMC_ASSERT(grid_s > 0 && !nodes_.empty(), "grid {} s, {} nodes", grid_s, nodes_.size());
}

Vec3 GridProcess::at(double t) const {
  if (nodes_.empty()) return Vec3::Zero();
  const double u = t / grid_s_;
  const auto last = static_cast<double>(nodes_.size() - 1);
  if (u >= last) return nodes_.back();
  if (u <= 0.0) return nodes_.front();
  const auto k = static_cast<std::size_t>(u);
  const double frac = u - static_cast<double>(k);
  return (1.0 - frac) * nodes_[k] + frac * nodes_[k + 1];
}

GridProcess::Integrals GridProcess::integrals(double t0, double t1) const {
  Integrals out{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  if (nodes_.empty() || t1 <= t0) return out;
  double s0 = t0;
  while (s0 < t1) {
    // The end of the grid segment holding s0 (or t1).
    double next_node = (std::floor(s0 / grid_s_) + 1.0) * grid_s_;
    if (next_node - s0 < 1e-9 * grid_s_) next_node += grid_s_;  // s0 on a node (round-off)
    const double s1 = std::min(t1, next_node);
    const double sm = 0.5 * (s0 + s1), len = s1 - s0;
    const Vec3 p0 = at(s0), pm = at(sm), p1 = at(s1);
    out.first += len / 6.0 * (p0 + 4.0 * pm + p1);
    out.second += len / 6.0 * ((t1 - s0) * p0 + 4.0 * (t1 - sm) * pm + (t1 - s1) * p1);
    out.third += len / 12.0 *
                 ((t1 - s0) * (t1 - s0) * p0 + 4.0 * (t1 - sm) * (t1 - sm) * pm + (t1 - s1) * (t1 - s1) * p1);
    s0 = s1;
  }
  return out;
}

void GridProcess::add(const GridProcess& other) {
  if (other.empty()) return;
  if (empty()) {
    *this = other;
    return;
  }
  INSMC_ASSERT(std::abs(grid_s_ - other.grid_s_) < 1e-12 * grid_s_, "grids {} and {}", grid_s_,
               other.grid_s_);
  const std::size_t n = std::max(nodes_.size(), other.nodes_.size());
  const Vec3 mine_last = nodes_.back();
  nodes_.resize(n, mine_last);
  for (std::size_t k = 0; k < n; ++k)
    nodes_[k] += other.nodes_[std::min(k, other.nodes_.size() - 1)];
}

}  // namespace insmc

namespace insmc {
namespace {

std::size_t node_count(double duration_s, double grid_s) {
  return static_cast<std::size_t>(std::ceil(duration_s / grid_s)) + 2;
}

Vec3 draw3(NormalDraws& d) {
  const double a = d.next(), b = d.next(), c = d.next();
  return Vec3(a, b, c);
}

}  // namespace

GridProcess make_gauss_markov(double sigma, double tau_s, double duration_s, double grid_s,
                              NormalDraws& draws) {
  if (tau_s <= 0.0) return make_random_walk(sigma, duration_s, grid_s, draws);
  const std::size_t n = node_count(duration_s, grid_s);
  const double phi = std::exp(-grid_s / tau_s);
  const double drive = sigma * std::sqrt(-std::expm1(-2.0 * grid_s / tau_s));
  std::vector<Vec3> nodes(n);
  nodes[0] = sigma * draw3(draws);
  for (std::size_t k = 1; k < n; ++k) nodes[k] = phi * nodes[k - 1] + drive * draw3(draws);
  return GridProcess(grid_s, std::move(nodes));
}

GridProcess make_random_walk(double sigma_1h, double duration_s, double grid_s, NormalDraws& draws) {
  const std::size_t n = node_count(duration_s, grid_s);
  const double step = sigma_1h * std::sqrt(grid_s / 3600.0);
  std::vector<Vec3> nodes(n);
  nodes[0] = Vec3::Zero();
  for (std::size_t k = 1; k < n; ++k) nodes[k] = nodes[k - 1] + step * draw3(draws);
  return GridProcess(grid_s, std::move(nodes));
}

}  // namespace insmc
