#include "montecarlo/report/json.h"

#include <cmath>
#include <fmt/format.h>

#include "lib/common/assert.h"

namespace insmc::mc {
namespace {

void escape_into(std::string& out, const std::string& s) {
  out += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) out += fmt::format("\\u{:04x}", c);
        else out += static_cast<char>(c);
    }
  }
  out += '"';
}

}  // namespace

Json& Json::operator[](const std::string& key) {
  if (std::holds_alternative<std::nullptr_t>(value_)) value_ = Object{};
  auto* obj = std::get_if<Object>(&value_);
  INSMC_ASSERT(obj != nullptr, "Json::operator[] on a non-object (key {})", key);
  for (auto& [k, v] : *obj)
    if (k == key) return v;
  obj->emplace_back(key, Json());
  return obj->back().second;
}

void Json::push_back(Json v) {
  if (std::holds_alternative<std::nullptr_t>(value_)) value_ = Array{};
  auto* arr = std::get_if<Array>(&value_);
  INSMC_ASSERT(arr != nullptr, "Json::push_back on a non-array");
  arr->push_back(std::move(v));
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  if (indent >= 0) out += '\n';
  return out;
}

void Json::dump_to(std::string& out, int indent, int depth) const {
  const auto newline = [&](int d) {
    if (indent < 0) return;
    out += '\n';
    out.append(static_cast<size_t>(indent * d), ' ');
  };
  if (std::holds_alternative<std::nullptr_t>(value_)) {
    out += "null";
  } else if (const bool* b = std::get_if<bool>(&value_)) {
    out += *b ? "true" : "false";
  } else if (const double* d = std::get_if<double>(&value_)) {
    if (!std::isfinite(*d)) out += "null";
    else if (*d == std::floor(*d) && std::abs(*d) < 1e15) out += fmt::format("{}", static_cast<long long>(*d));
    else out += fmt::format("{}", *d);  // shortest round-trip
  } else if (const std::string* s = std::get_if<std::string>(&value_)) {
    escape_into(out, *s);
  } else if (const Object* o = std::get_if<Object>(&value_)) {
    out += '{';
    for (size_t i = 0; i < o->size(); ++i) {
      if (i) out += ',';
      newline(depth + 1);
      escape_into(out, (*o)[i].first);
      out += indent >= 0 ? ": " : ":";
      (*o)[i].second.dump_to(out, indent, depth + 1);
    }
    if (!o->empty()) newline(depth);
    out += '}';
  } else if (const Array* a = std::get_if<Array>(&value_)) {
    out += '[';
    for (size_t i = 0; i < a->size(); ++i) {
      if (i) out += ',';
      newline(depth + 1);
      (*a)[i].dump_to(out, indent, depth + 1);
    }
    if (!a->empty()) newline(depth);
    out += ']';
  }
}

}  // namespace insmc::mc
