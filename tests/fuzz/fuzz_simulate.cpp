// libFuzzer target: `insmc simulate` whole, with the option combination the input chooses (tiny runs) (tests/fuzz/fuzz_entry.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tests/fuzz/fuzz_entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  insmc::fuzz::simulate(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
