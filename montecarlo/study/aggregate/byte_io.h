#pragma once
/// Little-endian byte encoding for aggregator serialize()/deserialize()
/// (ExactSum, OutputStats, KeptSamples).
/// Doubles are written as their IEEE-754 binary64 bit patterns, so a round
/// trip reproduces every bit (including -0 and NaN payloads). Byte order is
/// fixed by shifting, independent of the host's endianness.
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace insmc::mc::byte_io {

inline void put_u8(std::string& out, std::uint8_t v) { out.push_back(static_cast<char>(v)); }

inline void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

inline void put_u64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

inline void put_f64(std::string& out, double v) { put_u64(out, std::bit_cast<std::uint64_t>(v)); }

/// Sequential reader; every read checks the remaining length. `what` names
/// the type being read in error messages; reading starts at byte `start`.
class Reader {
 public:
  Reader(std::string_view bytes, const char* what, std::size_t start = 0)
      : bytes_(bytes), what_(what), pos_(start) {
    if (start > bytes_.size()) fail("start beyond the end");
  }

  std::uint8_t u8() {
    need(1);
    const std::uint8_t v = byte(0);
    pos_ += 1;
    return v;
  }

  std::uint32_t u32() {
    need(4);
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t{byte(i)} << (8 * i);
    pos_ += 4;
    return v;
  }

  std::uint64_t u64() {
    need(8);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{byte(i)} << (8 * i);
    pos_ += 8;
    return v;
  }

  double f64() { return std::bit_cast<double>(u64()); }

  /// Fails unless the whole string has been consumed.
  void expect_end() const {
    if (pos_ != bytes_.size()) fail("trailing bytes");
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(std::string(what_) + " deserialize: " + why + " (at byte " +
                             std::to_string(pos_) + " of " + std::to_string(bytes_.size()) + ")");
  }

  std::size_t remaining() const { return bytes_.size() - pos_; }
  /// Index of the next byte to be read.
  std::size_t position() const { return pos_; }

 private:
  void need(std::size_t n) const {
    if (bytes_.size() - pos_ < n) fail("truncated");
  }
  std::uint8_t byte(int i) const {
    return static_cast<std::uint8_t>(bytes_[pos_ + static_cast<std::size_t>(i)]);
  }

  std::string_view bytes_;
  const char* what_;
  std::size_t pos_ = 0;
};

}  // namespace insmc::mc::byte_io
