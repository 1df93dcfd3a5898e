// The instruments' block kernels give, for every kernel this CPU has, the
// bits of the scalar instruments (DeltaVCounter, PositionReadout of
// lib/preflight/instruments.h) on ordinary values, exact ties of the
// position rounding (x.5 resolutions, both signs), huge values, zero
// resolution and pulse (continuous outputs), and NaN.
#include "montecarlo/study/kernels/counter_kernels.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "lib/preflight/instruments.h"
#include "montecarlo/study/kernels/counter_loops.h"

namespace insmc::mc {
namespace {

constexpr ProductKernel kKernels[] = {ProductKernel::Generic, ProductKernel::Avx2, ProductKernel::Avx512};

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

/// Values that stress the roundings: random, exact ties at resolution q,
/// signed zeros, huge, NaN.
std::vector<double> stress_values(std::size_t n, double q, std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    switch (i % 7) {
      case 0: v[i] = (static_cast<double>(static_cast<int>(u(g))) + 0.5) * q; break;  // a tie
      case 1: v[i] = i % 2 ? -0.0 : 0.0; break;
      case 2: v[i] = 1e300 * u(g); break;
      case 3: v[i] = i % 3 ? u(g) : std::numeric_limits<double>::quiet_NaN(); break;
      default: v[i] = u(g);
    }
  }
  return v;
}

TEST(CounterKernels, RoundHalfAwayIsStdRoundBitForBit) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cases = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
                               0x1p52, -0x1p52, 0x1p52 + 1, 0x1p53 - 1, 4503599627370495.5, -4503599627370495.5,
                               1e300, -1e300, inf, -inf, 5e-324, -5e-324, 0.3, -0.3, 7.0, -7.0};
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  for (int i = 0; i < 100000; ++i) cases.push_back(u(g)), cases.push_back(std::floor(u(g)) + 0.5);
  for (const double x : cases) EXPECT_TRUE(same_bits(round_half_away(x), std::round(x))) << x;
  EXPECT_TRUE(std::isnan(round_half_away(std::numeric_limits<double>::quiet_NaN())));
}

TEST(CounterKernels, PositionReadingsAreThePositionReadoutsBits) {
  std::mt19937_64 g(3);
  for (const double q : {0.9144, 0.5, 0.1, 0.0})
    for (const std::size_t n : {1, 5, 8, 17, 1024}) {
      const std::vector<double> r0 = stress_values(n, q, g), error = stress_values(n, q, g);
      const double truth = 1234.5 * (q > 0 ? q : 1);
      for (ProductKernel kernel : kKernels) {
        if (!product_kernel_available(kernel)) continue;
        std::vector<double> first(n), datum(n);
        read_positions(kernel, {r0.data(), nullptr, nullptr, 0.25, q}, n, first.data());
        read_positions(kernel, {r0.data(), error.data(), first.data(), truth, q}, n, datum.data());
        for (std::size_t s = 0; s < n; ++s) {
          const PositionReadout readout(q, 0.25, 0.25 + r0[s]);
          const double want_first = position_reading_error(0.25, 0.25 + r0[s], q);
          const double want = readout.change_m(truth, truth + r0[s] + error[s]);
          ASSERT_TRUE(same_bits(first[s], want_first) || (std::isnan(first[s]) && std::isnan(want_first)))
              << product_kernel_name(kernel) << " q " << q << " sample " << s << ": " << first[s] << " vs " << want_first;
          ASSERT_TRUE(same_bits(datum[s], want) || (std::isnan(datum[s]) && std::isnan(want)))
              << product_kernel_name(kernel) << " q " << q << " sample " << s << ": " << datum[s] << " vs " << want;
        }
      }
    }
}

TEST(CounterKernels, PulseCountsAreTheDeltaVCountersBits) {
  std::mt19937_64 g(4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double dv : {0.03048, 0.01, 0.0})
    for (const bool sway : {false, true})
      for (const std::size_t n : {1, 7, 9, 1024}) {
        constexpr int kIntervals = 6;
        std::vector<double> phase(n), sway_start(n);
        for (std::size_t s = 0; s < n; ++s) phase[s] = unit(g), sway_start[s] = 0.01 * (unit(g) - 0.5);
        std::vector<std::vector<double>> error(kIntervals), sway_now(kIntervals);
        for (int k = 0; k < kIntervals; ++k) {
          error[k] = stress_values(n, dv > 0 ? dv : 0.1, g);
          sway_now[k].resize(n);
          for (double& v : sway_now[k]) v = 0.01 * (unit(g) - 0.5);
        }
        const double nominal[kIntervals + 1] = {0.0, 1.5, 3.25, 4.0, 7.75, 9.0, 12.5};
        for (ProductKernel kernel : kKernels) {
          if (!product_kernel_available(kernel)) continue;
          std::vector<double> counted(n, 0.0), datum(n);
          std::vector<DeltaVCounter> counters;
          for (std::size_t s = 0; s < n; ++s) counters.emplace_back(dv, phase[s] * dv);
          for (int k = 1; k <= kIntervals; ++k) {
            PulseInterval in{error[k - 1].data(), sway ? sway_now[k - 1].data() : nullptr,
                             sway ? sway_start.data() : nullptr, phase.data(), nominal[k], nominal[k] - nominal[k - 1],
                             dv, 10.0};
            count_pulses(kernel, in, n, counted.data(), datum.data());
            for (std::size_t s = 0; s < n; ++s) {
              const double v = sway ? nominal[k] + error[k - 1][s] + sway_now[k - 1][s] - sway_start[s]
                                    : nominal[k] + error[k - 1][s];
              const double want = counters[s].interval_error_mps2(v, nominal[k] - nominal[k - 1], 10.0);
              ASSERT_TRUE(same_bits(datum[s], want) || (std::isnan(datum[s]) && std::isnan(want)))
                  << product_kernel_name(kernel) << " dv " << dv << " sway " << sway << " interval " << k
                  << " sample " << s << ": " << datum[s] << " vs " << want;
            }
          }
        }
      }
}

}  // namespace
}  // namespace insmc::mc
