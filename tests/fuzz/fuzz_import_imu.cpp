// libFuzzer target: `insmc import-imu` whole: a still recording of the length, rate and clock the input chooses, with its options (tests/fuzz/fuzz_entry.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tests/fuzz/fuzz_entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  insmc::fuzz::import_imu(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
