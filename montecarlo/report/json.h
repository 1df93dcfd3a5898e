#pragma once
/// A minimal JSON writer for machine output (run.json, --format json):
/// objects keep insertion order so that the bytes are reproducible.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace insmc::mc {

class Json {
 public:
  Json() : value_(nullptr) {}
  Json(std::nullptr_t) : value_(nullptr) {}
  Json(bool b) : value_(b) {}
  Json(int v) : value_(static_cast<double>(v)) {}
  Json(long v) : value_(static_cast<double>(v)) {}
  Json(long long v) : value_(static_cast<double>(v)) {}
  Json(unsigned long v) : value_(static_cast<double>(v)) {}
  Json(unsigned long long v) : value_(static_cast<double>(v)) {}
  Json(double v) : value_(v) {}
  Json(const char* s) : value_(std::string(s)) {}
  Json(std::string s) : value_(std::move(s)) {}

  static Json object() { Json j; j.value_ = Object{}; return j; }
  static Json array() { Json j; j.value_ = Array{}; return j; }

  /// Object member (appended; replaced if the key exists).
  Json& operator[](const std::string& key);
  /// Array element.
  void push_back(Json v);

  /// Compact when indent < 0, else pretty with `indent` spaces. Numbers use
  /// the shortest representation that round-trips (integers exactly);
  /// non-finite numbers are written as null.
  std::string dump(int indent = 2) const;

 private:
  using Object = std::vector<std::pair<std::string, Json>>;
  using Array = std::vector<Json>;
  std::variant<std::nullptr_t, bool, double, std::string, Object, Array> value_;
  void dump_to(std::string& out, int indent, int depth) const;
};

}  // namespace insmc::mc
