#pragma once
/// What every reader shares: echoing a piece of the input in a one-line
/// message, and reading a whole file with a cap on its size.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "lib/common/input_error.h"

namespace insmc {

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

/// "1 MiB", "2 GiB", "512 bytes": a cap in messages.
std::string format_bytes(std::uint64_t bytes);

}  // namespace insmc
