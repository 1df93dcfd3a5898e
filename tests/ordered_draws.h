#pragma once
// Random draws taken in a fixed order. Draws written as the arguments of one
// call (f(e(rng), e(rng))) are taken in the order the compiler evaluates the
// arguments, which the language leaves open (g++ right to left, clang left
// to right): a test's data would differ between its two builds.
#include <array>
#include <cstddef>

namespace insmc::testing {

template <std::size_t N, class Distribution, class Engine>
std::array<double, N> ordered_draws(Distribution& d, Engine& rng) {
  std::array<double, N> z{};
  for (double& v : z) v = d(rng);
  return z;
}

}  // namespace insmc::testing
