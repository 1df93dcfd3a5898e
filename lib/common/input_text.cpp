#include "lib/common/input_text.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <system_error>

#include "lib/common/input_error.h"

namespace insmc {
namespace {

/// Length of the valid UTF-8 sequence starting at text[i], or 0 (RFC 3629:
/// no overlong forms, no surrogates, at most U+10FFFF).
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (b >= 0xC2 && b <= 0xDF) {
    n = 2;
  } else if (b >= 0xE0 && b <= 0xEF) {
    n = 3;
    if (b == 0xE0) lo = 0xA0;
    if (b == 0xED) hi = 0x9F;
  } else if (b >= 0xF0 && b <= 0xF4) {
    n = 4;
    if (b == 0xF0) lo = 0x90;
    if (b == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

}  // namespace

std::string echo_input(std::string_view text, std::size_t max_bytes) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size() && i < max_bytes) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out.push_back(static_cast<char>(c));
      ++i;
    } else if (c == '\n') {
      out += "\\n", ++i;
    } else if (c == '\t') {
      out += "\\t", ++i;
    } else if (c == '\r') {
      out += "\\r", ++i;
    } else if (const std::size_t n = c >= 0x80 ? utf8_length(text, i) : 0; n > 0 && i + n <= max_bytes) {
      out.append(text.substr(i, n));
      i += n;
    } else if (n > 0) {
      break;  // a character that would cross the cut
    } else {
      out += fmt::format("\\x{:02X}", c);
      ++i;
    }
  }
  if (i < text.size()) out += fmt::format("\u2026({} bytes)", text.size());
  return out;
}

std::string one_line_value(std::string_view text, std::size_t max_bytes) {
  std::string out = echo_input(text, max_bytes);
  std::size_t first = 0;
  while (first < out.size() && out[first] == ' ') ++first;
  std::size_t last = out.size();
  while (last > first && out[last - 1] == ' ') --last;
  std::string escaped;
  for (std::size_t i = 0; i < first; ++i) escaped += "\\x20";
  escaped.append(out, first, last - first);
  for (std::size_t i = last; i < out.size(); ++i) escaped += "\\x20";
  return escaped;
}

std::string format_bytes(std::uint64_t bytes) {
  constexpr std::uint64_t kKiB = 1024, kMiB = kKiB * 1024, kGiB = kMiB * 1024;
  if (bytes >= kGiB && bytes % kGiB == 0) return fmt::format("{} GiB", bytes / kGiB);
  if (bytes >= kMiB && bytes % kMiB == 0) return fmt::format("{} MiB", bytes / kMiB);
  if (bytes >= kKiB && bytes % kKiB == 0) return fmt::format("{} KiB", bytes / kKiB);
  return fmt::format("{} bytes", bytes);
}

std::string read_file_capped(const std::filesystem::path& path, std::uint64_t max_bytes, std::string_view what) {
  const std::string shown = echo_input(path.string(), 200);
  const auto fail_to = [&](std::string_view verb, const std::string& reason) {
    const std::string why = fmt::format("cannot {} the {}: {}", verb, what, reason);
    throw FileReadError(fmt::format("{}: {}", shown, why), why);
  };
  const auto fail = [&](const std::string& reason) { fail_to("read", reason); };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail("it is a directory");
  // stdio rather than an ifstream: fopen/fread report errno, and an ifstream
  // opens a directory without complaint and then reads nothing.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) fail_to("open", std::strerror(errno));
  std::string text;
  try {
    constexpr std::size_t kChunk = 1 << 16;
    while (true) {
      const std::uint64_t room = max_bytes + 1 - text.size();  // one byte past the cap tells "too large"
      const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, room));
      const std::size_t old = text.size();
      text.resize(old + want);
      const std::size_t got = std::fread(text.data() + old, 1, want, file.get());
      text.resize(old + got);
      if (text.size() > max_bytes)
        fail(fmt::format("larger than {}, the most a {} may hold", format_bytes(max_bytes), what));
      if (got < want) break;
    }
  } catch (const std::bad_alloc&) {
    fail(fmt::format("not enough memory for its {} bytes", text.size()));
  } catch (const std::length_error&) {
    fail("not enough memory");
  }
  if (std::ferror(file.get())) fail(std::strerror(errno));
  return text;
}

}  // namespace insmc
