#pragma once
// Shared helpers of the propagation tests: the times checked and the
// largest effect per uncertainty at its Table 3.1 bound.
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

}  // namespace insmc::testing
