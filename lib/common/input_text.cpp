#include "lib/common/input_text.h"

#include <fmt/format.h>

#include <algorithm>
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

namespace {

/// An open file read with a cap; its failures named as read_file_capped's.
class CappedFile {
 public:
  CappedFile(const std::filesystem::path& path, std::uint64_t max_bytes, std::string_view what)
      : shown_(echo_input(path.string(), 200)), what_(what), max_bytes_(max_bytes), file_(nullptr, &std::fclose) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail("it is a directory");
    // stdio rather than an ifstream: fopen/fread report errno, and an ifstream
    // opens a directory without complaint and then reads nothing.
    file_.reset(std::fopen(path.c_str(), "rb"));
    if (!file_) fail_to("open", std::strerror(errno));
  }

  std::size_t read(char* buffer, std::size_t size) {
    // One byte past the cap tells "too large".
    const std::uint64_t room = max_bytes_ + 1 - read_;
    const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(size, room));
    const std::size_t got = want == 0 ? 0 : std::fread(buffer, 1, want, file_.get());
    read_ += got;
    if (read_ > max_bytes_) fail(fmt::format("larger than {}, the most a {} may hold", format_bytes(max_bytes_), what_));
    if (got < want && std::ferror(file_.get())) fail(std::strerror(errno));
    return got;
  }

  [[noreturn]] void fail(const std::string& reason) const { fail_to("read", reason); }

 private:
  [[noreturn]] void fail_to(std::string_view verb, const std::string& reason) const {
    const std::string why = fmt::format("cannot {} the {}: {}", verb, what_, reason);
    throw FileReadError(fmt::format("{}: {}", shown_, why), why);
  }

  std::string shown_, what_;
  std::uint64_t max_bytes_, read_ = 0;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
};

}  // namespace

std::string read_file_capped(const std::filesystem::path& path, std::uint64_t max_bytes, std::string_view what) {
  CappedFile file(path, max_bytes, what);
  std::string text;
  try {
    constexpr std::size_t kChunk = 1 << 16;
    while (true) {
      const std::size_t old = text.size();
      text.resize(old + kChunk);
      const std::size_t got = file.read(text.data() + old, kChunk);
      text.resize(old + got);
      if (got == 0) break;
    }
  } catch (const std::bad_alloc&) {
    file.fail(fmt::format("not enough memory for its {} bytes", text.size()));
  } catch (const std::length_error&) {
    file.fail("not enough memory");
  }
  return text;
}

ByteSource capped_file_source(const std::filesystem::path& path, std::uint64_t max_bytes, std::string_view what) {
  auto file = std::make_shared<CappedFile>(path, max_bytes, what);
  return [file](char* buffer, std::size_t size) { return file->read(buffer, size); };
}

ByteSource text_source(std::string_view text) {
  return [text, at = std::size_t{0}](char* buffer, std::size_t size) mutable {
    const std::size_t n = std::min(size, text.size() - at);
    std::copy_n(text.data() + at, n, buffer);
    at += n;
    return n;
  };
}

LineReader::LineReader(ByteSource source, std::size_t max_line_bytes)
    : source_(std::move(source)), max_line_bytes_(max_line_bytes) {}

bool LineReader::fill() {
  if (end_) return false;
  constexpr std::size_t kChunk = 1 << 16;
  if (pos_ > 0) {  // keep only the unread part
    buffer_.erase(0, pos_);
    pos_ = 0;
  }
  const std::size_t old = buffer_.size();
  buffer_.resize(old + kChunk);
  const std::size_t got = source_(buffer_.data() + old, kChunk);
  buffer_.resize(old + got);
  end_ = got == 0;
  return got > 0;
}

bool LineReader::next(std::string_view& line, const std::function<void(std::size_t, bool)>& too_long) {
  std::size_t searched = pos_;
  for (;;) {
    const std::size_t nl = buffer_.find('\n', searched);
    if (nl != std::string::npos) {
      if (nl - pos_ > max_line_bytes_) too_long(nl - pos_, true);
      line = std::string_view(buffer_).substr(pos_, nl - pos_);
      pos_ = nl + 1;
      return true;
    }
    if (buffer_.size() - pos_ > max_line_bytes_) break;  // too long: measured below
    const std::size_t unread = buffer_.size() - pos_;
    if (!fill()) {
      if (unread == 0) return false;
      line = std::string_view(buffer_).substr(pos_);  // the last line, without a line ending
      pos_ = buffer_.size();
      return true;
    }
    searched = pos_ + unread;
  }
  // Count the rest of the long line without keeping it, up to 1 MiB more.
  constexpr std::size_t kMeasuredBeyond = std::size_t{1} << 20;
  std::size_t length = buffer_.size() - pos_;
  buffer_.clear();
  pos_ = 0;
  while (length <= max_line_bytes_ + kMeasuredBeyond) {
    if (!fill()) {
      too_long(length, true);
      break;
    }
    const std::size_t nl = buffer_.find('\n');
    if (nl != std::string::npos) too_long(length + nl, true);
    length += buffer_.size();
    buffer_.clear();
  }
  too_long(length, false);
  return false;  // too_long throws
}

}  // namespace insmc
