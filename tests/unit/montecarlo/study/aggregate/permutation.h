#pragma once
// A random permutation for the order-independence tests of the aggregators.
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

#include "montecarlo/study/random/philox.h"

namespace insmc::mc::testing {

/// A random permutation of 0..n-1 (Fisher–Yates on the Philox stream).
inline std::vector<std::size_t> permutation(std::size_t n, mc::CounterStream& rng) {
  std::vector<std::size_t> p(n);
  std::iota(p.begin(), p.end(), std::size_t{0});
  for (std::size_t i = n; i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng.uniform01() * static_cast<double>(i));
    std::swap(p[i - 1], p[j]);
  }
  return p;
}

}  // namespace insmc::mc::testing
