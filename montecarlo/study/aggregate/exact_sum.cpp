#include "montecarlo/study/aggregate/exact_sum.h"

#include <cmath>

#include "lib/common/assert.h"
#include "montecarlo/study/aggregate/byte_io.h"

namespace insmc::mc {
namespace {

__extension__ typedef unsigned __int128 u128;  // GCC extension, exact 128-bit carries

}  // namespace

void ExactSum::add(double x) {
  INSMC_ASSERT(std::isfinite(x) && std::abs(x) < 0x1p250, "ExactSum::add({})", x);
  if (x == 0.0) return;
  int e = 0;
  const double m = std::frexp(std::abs(x), &e);  // |x| = m 2^e, m in [0.5, 1)
  std::uint64_t mant = static_cast<std::uint64_t>(std::ldexp(m, 53));  // exact, < 2^53
  int pos = e - 53 + kFractionBits;  // bit position of mant's least significant bit
  if (pos < 0) {
    if (pos <= -64) return;  // below the resolution: truncated to zero
    mant >>= -pos;
    pos = 0;
    if (mant == 0) return;
  }
  const int limb = pos / 64, shift = pos % 64;
  const u128 chunk = static_cast<u128>(mant) << shift;  // ≤ 116 bits
  const std::uint64_t parts[2] = {static_cast<std::uint64_t>(chunk), static_cast<std::uint64_t>(chunk >> 64)};
  if (x > 0) {
    std::uint64_t carry = 0;
    for (int i = limb; i < kLimbs; ++i) {
      const std::uint64_t addend = (i - limb < 2) ? parts[i - limb] : 0;
      const u128 s = static_cast<u128>(limbs_[i]) + addend + carry;
      limbs_[i] = static_cast<std::uint64_t>(s);
      carry = static_cast<std::uint64_t>(s >> 64);
      if (i - limb >= 1 && carry == 0) break;
    }
  } else {
    std::uint64_t borrow = 0;
    for (int i = limb; i < kLimbs; ++i) {
      const std::uint64_t sub = (i - limb < 2) ? parts[i - limb] : 0;
      const u128 d = static_cast<u128>(limbs_[i]) - sub - borrow;
      limbs_[i] = static_cast<std::uint64_t>(d);
      borrow = static_cast<std::uint64_t>(d >> 64) ? 1 : 0;
      if (i - limb >= 1 && borrow == 0) break;
    }
  }
}

void ExactSum::merge(const ExactSum& other) {
  std::uint64_t carry = 0;
  for (int i = 0; i < kLimbs; ++i) {
    const u128 s = static_cast<u128>(limbs_[i]) + other.limbs_[i] + carry;
    limbs_[i] = static_cast<std::uint64_t>(s);
    carry = static_cast<std::uint64_t>(s >> 64);
  }
}

double ExactSum::value() const {
  std::array<std::uint64_t, kLimbs> mag = limbs_;
  const bool negative = (mag[kLimbs - 1] >> 63) != 0;
  if (negative) {  // two's complement negation
    std::uint64_t carry = 1;
    for (auto& l : mag) {
      const u128 s = static_cast<u128>(~l) + carry;
      l = static_cast<std::uint64_t>(s);
      carry = static_cast<std::uint64_t>(s >> 64);
    }
  }
  long double acc = 0.0L;
  for (int i = kLimbs - 1; i >= 0; --i) acc = acc * 0x1p64L + static_cast<long double>(mag[i]);
  const double v = static_cast<double>(std::ldexp(acc, -kFractionBits));
  return negative ? -v : v;
}

void ExactSum::append_to(std::string& out) const {
  for (std::uint64_t l : limbs_) byte_io::put_u64(out, l);
}

ExactSum ExactSum::read_from(std::string_view bytes, std::size_t& pos) {
  byte_io::Reader in(bytes, "ExactSum", pos);
  ExactSum s;
  for (auto& l : s.limbs_) l = in.u64();
  pos = in.position();
  return s;
}

}  // namespace insmc::mc
