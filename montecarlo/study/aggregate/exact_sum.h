#pragma once
/// An exactly associative sum of doubles, so that Monte Carlo totals are the
/// same bits however the samples were split across threads and processes.
///
/// Each added double is truncated (toward zero) to a multiple of 2^-128 and
/// accumulated in a 384-bit two's-complement fixed-point register: integer
/// additions are exact, so any grouping of the same adds gives the same
/// register. Range ±2^255; resolution 2^-128 ≈ 2.9e-39 (far below any
/// meaningful position error or its powers).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace insmc::mc {

class ExactSum {
 public:
  /// Adds x (finite, |x| < 2^250; a programmer error otherwise).
  void add(double x);
  void merge(const ExactSum& other);
  /// The sum rounded to double (deterministic; a few ulps).
  double value() const;

  void append_to(std::string& out) const;
  /// Reads 48 bytes at `pos`, advancing it; throws std::runtime_error when short.
  static ExactSum read_from(std::string_view bytes, std::size_t& pos);

  friend bool operator==(const ExactSum&, const ExactSum&) = default;

 private:
  static constexpr int kLimbs = 6;
  static constexpr int kFractionBits = 128;
  std::array<std::uint64_t, kLimbs> limbs_{};
};

}  // namespace insmc::mc
