#include "lib/common/enum_names.h"
#include "lib/common/system.h"

#include "lib/common/input_error.h"

namespace insmc {

System parse_system(std::string_view text, std::string_view field) {
  if (text == "1") return System::kTheodolite;
  if (text == "2") return System::kGyrocompass;
  throw InputError(std::string(field), std::string(text),
                   "must be 1 (theodolite azimuth) or 2 (gyrocompassing)");
}

namespace {
constexpr EnumName<Fidelity> kFidelityNames[] = {
    {Fidelity::kPaper, "paper"}, {Fidelity::kLinear, "linear"}, {Fidelity::kTruth, "truth"}};
}  // namespace

std::string_view to_string(Fidelity f) { return name_of<Fidelity>(kFidelityNames, f); }

Fidelity parse_fidelity(std::string_view text, std::string_view field) {
  if (const auto f = value_named<Fidelity>(kFidelityNames, text)) return *f;
  throw InputError(std::string(field), std::string(text), "must be paper, linear or truth");
}

}  // namespace insmc
