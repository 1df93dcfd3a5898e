// parse_quantity's input cap and escaped echoes.
#include <gtest/gtest.h>

#include <string>

#include "lib/common/input_error.h"
#include "lib/units/quantity.h"

namespace insmc {
namespace {

std::string error_of(const std::string& text, Dimension d) {
  try {
    parse_quantity(text, d, "--x");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(QuantityCaps, AHugeValueIsRefusedAndCut) {
  const std::string e = error_of(std::string(100'000, '1') + "s", Dimension::kTime);
  EXPECT_NE(e.find("--x = " + std::string(40, '1') + "\u2026(100001 bytes): 100001 bytes: a value holds at most 256"),
            std::string::npos)
      << e.substr(0, 300);
  EXPECT_LT(e.size(), 400u);
}

TEST(QuantityCaps, ControlBytesAreEscaped) {
  const std::string e = error_of("5\x1b[31mm", Dimension::kLength);
  EXPECT_EQ(e.find('\x1b'), std::string::npos) << e;
  EXPECT_NE(e.find("--x = 5\\x1B[31mm: unknown unit '\\x1B[31mm'"), std::string::npos) << e;
  EXPECT_NE(error_of(std::string("5\0m", 3), Dimension::kLength).find("--x = 5\\x00m: not a number"), std::string::npos);
}

TEST(QuantityCaps, OverflowOnConversionIsRefused) {
  EXPECT_NE(error_of("1e308nmi", Dimension::kLength).find("must be finite"), std::string::npos);
  EXPECT_EQ(error_of("1e300nmi", Dimension::kLength), "(accepted)");
}

}  // namespace
}  // namespace insmc
