#include "montecarlo/study/run/run_file.h"

#include <array>
#include <fmt/format.h>
#include <istream>
#include <nlohmann/json.hpp>
#include <streambuf>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"

namespace insmc::mc {
namespace {

/// Reads settings.arguments with nlohmann's SAX interface: memory follows
/// the arguments, not the file (a run.json holds the whole envelope), and a
/// nesting deeper than insmc ever writes is refused as it is met.
class ArgumentsReader final : public nlohmann::json_sax<nlohmann::json> {
 public:
  using json = nlohmann::json;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(json::number_integer_t) override { return value(); }
  bool number_unsigned(json::number_unsigned_t) override { return value(); }
  bool number_float(json::number_float_t, const json::string_t&) override { return value(); }
  bool binary(json::binary_t&) override { return value(); }
  bool string(json::string_t& s) override {
    if (!in_arguments()) return value();
    if (s.rfind("--", 0) != 0 || s.size() > kMaxRunArgumentBytes) {
      problem = fmt::format("settings.arguments[{}] must be an option \"--name=value\" of at most {} bytes",
                            arguments.size(), kMaxRunArgumentBytes);
      return false;
    }
    if (arguments.size() >= kMaxRunArguments) {
      problem = fmt::format("settings.arguments holds more than {} values", kMaxRunArguments);
      return false;
    }
    arguments.push_back(std::move(s));
    return true;
  }
  bool start_object(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    if (depth_ == 2 && key_ == "arguments" && under_settings_) {
      if (found) {
        problem = "holds settings.arguments twice";
        return false;
      }
      found = true;
      arguments_depth_ = depth_ + 1;
    }
    return open(true);
  }
  bool end_array() override { return close(); }
  bool key(json::string_t& k) override {
    key_ = std::move(k);
    if (depth_ == 1) under_settings_next_ = key_ == "settings";
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    if (problem.empty()) problem = "is not JSON (a run.json written by insmc run)";
    return false;
  }

  std::vector<std::string> arguments;
  bool found = false;
  std::string problem;

 private:
  /// insmc writes run.json four levels deep; the envelope rows are objects
  /// in an array in an object.
  static constexpr int kMaxDepth = 32;

  bool in_arguments() const { return arguments_depth_ > 0 && depth_ == arguments_depth_; }
  bool value() {
    if (in_arguments()) {
      problem = fmt::format("settings.arguments[{}] must be an option \"--name=value\" of at most {} bytes",
                            arguments.size(), kMaxRunArgumentBytes);
      return false;
    }
    return true;
  }
  bool open(bool array) {
    if (in_arguments()) return value();
    if (depth_ == 0 && array) {
      problem = "has no settings.arguments array (a run.json of insmc run 0.1.0 or later)";
      return false;
    }
    if (++depth_ > kMaxDepth) {
      problem = fmt::format("nests deeper than {} levels (insmc writes 4)", kMaxDepth);
      return false;
    }
    if (depth_ == 2) under_settings_ = !array && under_settings_next_;  // settings is an object
    return true;
  }
  bool close() {
    if (depth_ == arguments_depth_) arguments_depth_ = 0;
    if (depth_ == 2) under_settings_ = false;
    --depth_;
    return true;
  }

  int depth_ = 0, arguments_depth_ = 0;
  std::string key_;
  bool under_settings_ = false, under_settings_next_ = false;
};

/// The bytes of a ByteSource as a stream buffer, a chunk at a time.
class SourceBuffer final : public std::streambuf {
 public:
  explicit SourceBuffer(ByteSource source) : source_(std::move(source)) {}

 protected:
  int_type underflow() override {
    const std::size_t got = source_(chunk_.data(), chunk_.size());
    if (got == 0) return traits_type::eof();
    setg(chunk_.data(), chunk_.data(), chunk_.data() + got);
    return traits_type::to_int_type(chunk_[0]);
  }

 private:
  ByteSource source_;
  std::array<char, 1 << 16> chunk_{};
};

/// settings.arguments as `parse` (one of nlohmann's sax_parse) reads them.
template <class Parse>
std::vector<std::string> arguments_read_by(Parse&& parse, std::string_view source) {
  ArgumentsReader reader;
  const bool parsed = parse(reader);
  if (!parsed || !reader.found)
    throw InputError("--from", echo_input(std::string(source)),
                     !reader.problem.empty() ? reader.problem
                                             : "has no settings.arguments array (a run.json of insmc run 0.1.0 or later)");
  return std::move(reader.arguments);
}

}  // namespace

std::vector<std::string> run_arguments_from_json(std::string_view text, std::string_view source) {
  return arguments_read_by(
      [&](ArgumentsReader& reader) { return nlohmann::json::sax_parse(text.begin(), text.end(), &reader); }, source);
}

std::vector<std::string> read_run_arguments(const std::string& path) {
  // Parsed as it is read: memory follows the arguments (and the longest
  // token, within the cap), never the file; /dev/zero stops at its first byte.
  SourceBuffer buffer(capped_file_source(path, kMaxRunJsonBytes, "--from file"));
  std::istream in(&buffer);
  return arguments_read_by([&](ArgumentsReader& reader) { return nlohmann::json::sax_parse(in, &reader); }, path);
}

}  // namespace insmc::mc
