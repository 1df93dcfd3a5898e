#include "montecarlo/records/gap/null/bootstrap.h"

#include <algorithm>
#include <limits>
#include <functional>
#include <cmath>

#include "montecarlo/study/random/philox.h"

namespace insmc::gap {

std::vector<int> all_runs(std::size_t n) {
  std::vector<int> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<int>(i);
  return v;
}

std::vector<int> resample(std::uint64_t seed, std::uint64_t b, int n, int pool) {
  mc::CounterStream s(seed, mc::Stream::Bootstrap, b);
  std::vector<int> idx(static_cast<std::size_t>(n));
  for (int& i : idx) i = std::min(pool - 1, static_cast<int>(s.uniform01() * pool));
  return idx;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(pos);
  const double w = pos - static_cast<double>(i);
  return i + 1 < v.size() ? (1 - w) * v[i] + w * v[i + 1] : v[i];
}

double p_value_of(double observed, const std::vector<double>& null) {
  const auto above = std::count_if(null.begin(), null.end(), [&](double g) { return g >= observed; });
  return (1.0 + static_cast<double>(above)) / (1.0 + static_cast<double>(null.size()));
}

double critical_value(std::vector<double> null, double alpha) {
  if (null.empty()) return 0.0;
  const double k = std::floor(alpha * (static_cast<double>(null.size()) + 1.0)) - 1.0;
  if (k < 0) return std::numeric_limits<double>::infinity();
  const auto at = std::min(static_cast<std::size_t>(k), null.size() - 1);
  std::nth_element(null.begin(), null.begin() + static_cast<std::ptrdiff_t>(at), null.end(), std::greater<>());
  return null[at];
}

}  // namespace insmc::gap
