// libFuzzer target: the option parser (tests/fuzz/fuzz_entry.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tests/fuzz/fuzz_entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  insmc::fuzz::options(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
