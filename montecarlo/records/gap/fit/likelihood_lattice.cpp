#include "montecarlo/records/gap/fit/likelihood_lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lib/common/assert.h"

namespace insmc::gap {

LikelihoodLattice::LikelihoodLattice(std::vector<FitParameter> parameters, RunLogLikelihoods evaluate, int runs,
                                     double step)
    : parameters_(std::move(parameters)), evaluate_(std::move(evaluate)), runs_(runs) {
  INSMC_ASSERT(step > 1.0, "lattice step {} must exceed 1", step);
  for (const FitParameter& p : parameters_) {
    INSMC_ASSERT(p.lower_si > 0.0 && p.upper_si >= p.lower_si, "parameter {}: limits {}..{} not a log range", p.name,
                 p.lower_si, p.upper_si);
    // The range divided into equal log steps no larger than `step`, so that
    // both physical limits are lattice points.
    const double range = std::log(p.upper_si / p.lower_si);
    const int last = std::max(0, static_cast<int>(std::ceil(range / std::log(step) - 1e-9)));
    last_.push_back(last);
    log_step_.push_back(last > 0 ? range / last : std::log(step));
  }
}

int LikelihoodLattice::per_decade(int p) const {
  return std::max(1, static_cast<int>(std::lround(std::log(10.0) / log_step_[static_cast<std::size_t>(p)])));
}

double LikelihoodLattice::value(int p, int k) const {
  const FitParameter& q = parameter(p);
  if (k >= last(p)) return q.upper_si;  // exact at the limits
  if (k <= 0) return q.lower_si;
  return q.lower_si * std::exp(k * log_step_[static_cast<std::size_t>(p)]);
}

int LikelihoodLattice::nearest(int p, double value_si) const {
  if (!(value_si > 0.0)) return 0;
  const double k = std::log(value_si / parameter(p).lower_si) / log_step_[static_cast<std::size_t>(p)];
  return std::clamp(static_cast<int>(std::lround(k)), 0, last(p));
}

std::vector<double> LikelihoodLattice::values(std::span<const int> index) const {
  std::vector<double> v(index.size());
  for (std::size_t p = 0; p < index.size(); ++p) v[p] = value(static_cast<int>(p), index[p]);
  return v;
}

const std::vector<double>& LikelihoodLattice::per_run(std::span<const int> index) {
  INSMC_ASSERT(static_cast<int>(index.size()) == dimensions(), "lattice point of {} parameters, expected {}",
               index.size(), dimensions());
  std::vector<int> key(index.begin(), index.end());
  auto it = cache_.find(key);
  if (it != cache_.end()) return it->second;
  std::vector<double> v = evaluate_(values(index));
  INSMC_ASSERT(static_cast<int>(v.size()) == runs_, "evaluation gave {} runs, expected {}", v.size(), runs_);
  for (double& x : v)
    if (std::isnan(x)) x = -std::numeric_limits<double>::infinity();
  return cache_.emplace(std::move(key), std::move(v)).first->second;
}

double LikelihoodLattice::sum(std::span<const int> index, std::span<const int> runs) {
  const std::vector<double>& v = per_run(index);
  double s = 0.0;
  for (int r : runs) s += v[static_cast<std::size_t>(r)];
  return s;
}

}  // namespace insmc::gap
