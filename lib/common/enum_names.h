#pragma once
/// An enumeration's spellings written once, as a table, for both
/// directions: to_string (value → name) and the parsers (name → value).
#include <optional>
#include <span>
#include <string_view>

namespace insmc {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

/// The name of `value` in `names`; "?" for a value the table lacks.
template <class E>
constexpr std::string_view name_of(std::span<const EnumName<E>> names, E value) {
  for (const EnumName<E>& n : names)
    if (n.value == value) return n.name;
  return "?";
}

/// The value spelled `text` in `names`, if any (the caller says what is allowed).
template <class E>
constexpr std::optional<E> value_named(std::span<const EnumName<E>> names, std::string_view text) {
  for (const EnumName<E>& n : names)
    if (n.name == text) return n.value;
  return std::nullopt;
}

}  // namespace insmc
