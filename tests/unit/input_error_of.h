#pragma once
// The one-line message of the InputError that `read()` throws, or
// "(accepted)" when it throws none: what the readers' tests compare; and
// the InputError a check throws, if any.
#include <optional>
#include <string>

#include "lib/common/input_error.h"

namespace insmc::test {

template <class Read>
std::string input_error_of(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

/// The InputError that `check()` throws, if any (a validate() call).
template <class Check>
std::optional<InputError> thrown_by(Check&& check) {
  try {
    check();
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

}  // namespace insmc::test
