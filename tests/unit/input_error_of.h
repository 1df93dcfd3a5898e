#pragma once
// The one-line message of the InputError that `read()` throws, or
// "(accepted)" when it throws none: what the readers' tests compare.
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

}  // namespace insmc::test
