#include "montecarlo/study/run/checkpoint.h"

#include <algorithm>
#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/common/version.h"
#include "montecarlo/study/aggregate/byte_io.h"
#include "montecarlo/study/write/study_writer.h"

namespace insmc::mc {
namespace {

constexpr std::string_view kMagic = "insmc checkpoint\n";

void put_string(std::string& out, std::string_view s) {
  byte_io::put_u64(out, s.size());
  out.append(s);
}

/// Reads the fields in order; a short file is an InputError naming the path.
class FieldReader {
 public:
  FieldReader(std::string_view bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  std::uint64_t u64() { return number(8); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(number(4)); }
  std::string string() {
    const std::uint64_t n = u64();
    need(n);
    std::string s(bytes_.substr(pos_, n));
    pos_ += n;
    return s;
  }
  std::size_t position() const { return pos_; }
  [[noreturn]] void fail(const std::string& why) const { throw InputError("--resume", echo_input(path_, 256), why); }

 private:
  std::uint64_t number(int size) {
    need(static_cast<std::uint64_t>(size));
    std::uint64_t v = 0;
    for (int i = 0; i < size; ++i)
      v |= std::uint64_t{static_cast<unsigned char>(bytes_[pos_ + static_cast<std::size_t>(i)])} << (8 * i);
    pos_ += static_cast<std::size_t>(size);
    return v;
  }
  void need(std::uint64_t n) const {
    if (n > bytes_.size() - pos_) fail("the checkpoint is truncated or corrupt");
  }
  std::string_view bytes_;
  const std::string& path_;
  std::size_t pos_ = 0;
};

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char ch : bytes) {
    h ^= static_cast<unsigned char>(ch);
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::string encode_checkpoint(const Checkpoint& c) {
  std::string out(kMagic);
  out.reserve(c.state.size() + 4096);
  byte_io::put_u32(out, kCheckpointFormat);
  put_string(out, c.version);
  byte_io::put_u64(out, c.args.size());
  for (const std::string& a : c.args) put_string(out, a);
  put_string(out, c.settings);
  byte_io::put_u64(out, c.fingerprint);
  byte_io::put_u64(out, c.samples);
  byte_io::put_u64(out, c.done.size());
  for (const BlockRange& r : c.done) {
    byte_io::put_u64(out, r.begin);
    byte_io::put_u64(out, r.end);
  }
  put_string(out, c.state);
  byte_io::put_u64(out, fnv1a64(out));
  return out;
}

Checkpoint decode_checkpoint(std::string_view bytes, const std::string& path) {
  if (bytes.substr(0, kMagic.size()) != kMagic)
    throw InputError("--resume", echo_input(path, 256), "not an insmc checkpoint file");
  // The format number and the version come first and never move, so that a
  // checkpoint of another insmc is named as such rather than as corrupt.
  FieldReader r(bytes.substr(kMagic.size()), path);
  Checkpoint c;
  const std::uint32_t format = r.u32();
  if (format != kCheckpointFormat)
    r.fail(fmt::format("checkpoint format {}; this insmc reads format {}", format, kCheckpointFormat));
  c.version = r.string();
  const bool printable = c.version.size() <= 64 && std::all_of(c.version.begin(), c.version.end(), [](char ch) {
                           return ch > ' ' && ch < 127;
                         });
  if (!printable) r.fail("the checkpoint is corrupt (version field)");
  if (c.version != kVersion)
    r.fail(fmt::format("written by insmc {}; resume it with that version (this is insmc {})", c.version, kVersion));
  const std::string_view body = bytes.substr(0, bytes.size() - std::min<std::size_t>(8, bytes.size()));
  if (bytes.size() < kMagic.size() + 8 || fnv1a64(body) != FieldReader(bytes.substr(body.size()), path).u64())
    r.fail("the checkpoint is corrupt (checksum mismatch)");
  const std::uint64_t argc = r.u64();
  if (argc > kMaxCheckpointArgs)
    r.fail(fmt::format("the checkpoint is corrupt ({} arguments; at most {})", argc, kMaxCheckpointArgs));
  for (std::uint64_t i = 0; i < argc; ++i) c.args.push_back(r.string());
  c.settings = r.string();
  c.fingerprint = r.u64();
  c.samples = r.u64();
  const std::uint64_t ranges = r.u64();
  if (ranges > kMaxCheckpointRanges)
    r.fail(fmt::format("the checkpoint is corrupt ({} block ranges; at most {})", ranges, kMaxCheckpointRanges));
  for (std::uint64_t i = 0; i < ranges; ++i) {
    BlockRange range;
    range.begin = r.u64();
    range.end = r.u64();
    if (range.end < range.begin) r.fail("the checkpoint is corrupt (block range)");
    c.done.push_back(range);
  }
  c.state = r.string();
  r.u64();  // the checksum, verified above
  if (kMagic.size() + r.position() != bytes.size()) r.fail("the checkpoint is corrupt (trailing bytes)");
  return c;
}

std::string read_checkpoint_file(const std::string& path) {
  const ByteSource file = capped_file_source(path, kMaxCheckpointFileBytes, "checkpoint");
  std::string bytes;
  const auto read_more = [&](std::size_t want) {
    const std::size_t old = bytes.size();
    bytes.resize(old + want);
    const std::size_t got = file(bytes.data() + old, want);
    bytes.resize(old + got);
    return got;
  };
  // The magic line first: anything else (/dev/zero, a text) is not read on,
  // never held up to the cap; decode_checkpoint says what it is not.
  while (bytes.size() < kMagic.size() && read_more(kMagic.size() - bytes.size()) > 0) {
  }
  if (bytes != kMagic) return bytes;
  while (read_more(std::size_t{1} << 16) > 0) {
  }
  return bytes;
}

std::uint64_t study_fingerprint(const StudyConfig& config, const StudyMap& map) {
  StudyConfig c = config;
  c.threads = 0;
  return fnv1a64(settings_json(c).dump() + StudyAccumulator(map).serialize());
}

}  // namespace insmc::mc
