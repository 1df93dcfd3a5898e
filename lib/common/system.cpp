#include "lib/common/system.h"

#include "lib/common/input_error.h"

namespace insmc {

System parse_system(std::string_view text, std::string_view field) {
  if (text == "1") return System::kTheodolite;
  if (text == "2") return System::kGyrocompass;
  throw InputError(std::string(field), std::string(text),
                   "must be 1 (theodolite azimuth) or 2 (gyrocompassing)");
}

std::string_view to_string(Fidelity f) {
  switch (f) {
    case Fidelity::kPaper: return "paper";
    case Fidelity::kLinear: return "linear";
    case Fidelity::kTruth: return "truth";
  }
  return "?";
}

Fidelity parse_fidelity(std::string_view text, std::string_view field) {
  if (text == "paper") return Fidelity::kPaper;
  if (text == "linear") return Fidelity::kLinear;
  if (text == "truth") return Fidelity::kTruth;
  throw InputError(std::string(field), std::string(text), "must be paper, linear or truth");
}

}  // namespace insmc
