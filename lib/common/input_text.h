#pragma once
/// What every reader shares: blanks and trimming, echoing a piece of the
/// input in a one-line message, and reading a whole file with a cap on its
/// size.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>

#include "lib/common/input_error.h"

namespace insmc {

/// A blank inside a line of text, for every reader: space, tab, CR, VT, FF
/// (a line break ends the line before it is looked at).
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
inline std::string_view trim_left(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  return s;
}
inline std::string_view trim_right(std::string_view s) {
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}
/// `s` without the blanks at its ends.
inline std::string_view trim(std::string_view s) { return trim_right(trim_left(s)); }

/// How much of an input value a message shows: enough to recognise it,
/// little enough that a megabyte-long value keeps the message on one line.
inline constexpr std::size_t kEchoMaxBytes = 40;

/// `text` made safe for a one-line message: control bytes, DEL and bytes
/// that are not valid UTF-8 become \n, \t, \r or \xNN (never written raw to
/// a terminal), valid UTF-8 is kept; text longer than `max_bytes` is cut
/// (at a character boundary) and followed by "…(N bytes)", N the full size.
/// No quotes are added.
std::string echo_input(std::string_view text, std::size_t max_bytes = kEchoMaxBytes);

/// `text` as one header value of a written file (`key=value` on one line,
/// no blanks at its ends): escaped as echo_input does, cut beyond
/// `max_bytes`, and a blank at either end written \x20.
std::string one_line_value(std::string_view text, std::size_t max_bytes = 4096);

/// What read_file_capped throws: an InputError whose message names the file
/// ("PATH: cannot read the record file: it is a directory") and whose why()
/// is the rest ("cannot read the record file: it is a directory"), for
/// callers that name the file themselves.
class FileReadError : public InputError {
 public:
  FileReadError(const std::string& message, std::string why) : InputError(message), why_(std::move(why)) {}
  const std::string& why() const { return why_; }

 private:
  std::string why_;
};

/// Reads the whole file at `path` if it holds at most `max_bytes` bytes,
/// never more than `max_bytes` + 1 (so /dev/zero or a huge file stop at the
/// cap). `what` names the file in messages ("record file", "--config file").
/// Throws FileReadError (naming the path, echoed) when the file cannot be
/// opened, is a directory, cannot be read (including running out of
/// memory), or is larger than `max_bytes`, with the cap in the message.
std::string read_file_capped(const std::filesystem::path& path, std::uint64_t max_bytes, std::string_view what);

/// Bytes in order from somewhere (a file, a string): fills `buffer` with up
/// to `size` bytes and returns how many, 0 at the end.
using ByteSource = std::function<std::size_t(char* buffer, std::size_t size)>;

/// The bytes of the file at `path` as a ByteSource that reads as it is
/// called, so that a reader holds a line at a time, never the file; the same
/// checks and messages as read_file_capped (a directory, an open or read
/// error, more than `max_bytes`: FileReadError), raised as they are met.
ByteSource capped_file_source(const std::filesystem::path& path, std::uint64_t max_bytes, std::string_view what);

/// The bytes of `text` as a ByteSource (text must outlive it).
ByteSource text_source(std::string_view text);

/// Lines of a ByteSource, each without its line ending, held one at a
/// time: memory is the longest line, never the input. A line longer than
/// `max_line_bytes` is measured (up to 1 MiB more, so that an endless one
/// such as /dev/zero stops there) and reported by `too_long`.
class LineReader {
 public:
  LineReader(ByteSource source, std::size_t max_line_bytes);
  /// The next line (valid until the next call) and false at the end. When
  /// the line is longer than the cap, `too_long(length, measured_all)` is
  /// called instead (it must throw): `length` its bytes, or the bytes seen
  /// when `measured_all` is false.
  bool next(std::string_view& line, const std::function<void(std::size_t, bool)>& too_long);

 private:
  bool fill();
  ByteSource source_;
  std::size_t max_line_bytes_;
  std::string buffer_;
  std::size_t pos_ = 0;
  bool end_ = false;
};

/// "1 MiB", "2 GiB", "512 bytes": a cap in messages.
std::string format_bytes(std::uint64_t bytes);

}  // namespace insmc
