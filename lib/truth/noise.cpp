#include "lib/truth/noise.h"

#include <cmath>
#include <numbers>

namespace insmc {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// (k + 0.5) 2^-53 for the top 53 bits k: in (0, 1), never 0.
double open_uniform(std::uint64_t bits) {
  return (static_cast<double>(bits >> 11) + 0.5) * 0x1p-53;
}

}  // namespace

double hashed_standard_normal(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter) {
  const std::uint64_t base = splitmix64(splitmix64(seed) ^ splitmix64(stream + 0x632BE59BD9B4E019ull));
  const std::uint64_t h1 = splitmix64(base ^ (2 * counter));
  const std::uint64_t h2 = splitmix64(base ^ (2 * counter + 1));
  const double u1 = open_uniform(h1), u2 = open_uniform(h2);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double NormalDraws::next_uniform() {
  const double z = next();
  return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}

}  // namespace insmc
