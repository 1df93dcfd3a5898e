#pragma once
// Shared helpers of the model-level tests: the times checked, the largest
// effect per uncertainty at its Table 3.1 bound, spread draws within the bounds.
#include <cstdint>
#include <string>
#include <vector>

#include "lib/uncertainty/catalogue.h"
#include "lib/units/units.h"

namespace insmc::testing {

/// 1..90 min each minute: includes 42, 63 and 84 min and stays within the
/// report's 1.5 h validity.
inline std::vector<double> minutes_1_to_90() {
  std::vector<double> t;
  for (int m = 1; m <= 90; ++m) t.push_back(60.0 * m);
  return t;
}

/// max over axes of |a − b| for uncertainty `i` at its default bound, in ft.
template <class A, class B>
double difference_at_bound_ft(const A& a, const B& b, int i) {
  return (a.col(i) - b.col(i)).cwiseAbs().maxCoeff() * default_bounds()[i] / kFtToM;
}

inline std::string name_of(int i) { return std::string(catalogue()[i].name); }

/// Every uncertainty uniform within its Table 3.1 bound, from a fixed linear
/// congruential sequence per seed (spread values, not a distribution test).
inline UncertaintyVector within_bounds(std::uint64_t seed) {
  std::uint64_t state = 0x9e3779b97f4a7c15ull * (seed + 1);
  const UncertaintyVector b = default_bounds();
  UncertaintyVector x;
  for (int i = 0; i < uncertainty_slot::kDim; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    x[i] = b[i] * (2.0 * (static_cast<double>(state >> 11) * 0x1.0p-53) - 1.0);
  }
  return x;
}

}  // namespace insmc::testing
