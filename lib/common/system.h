#pragma once
/// The two alignment concepts of the report (chapter 2), and the fidelity
/// levels (`--fidelity paper|linear|truth`, docs/truth-vs-models.md), each
/// with its one to_string/parse pair.
#include <string>
#include <string_view>

namespace insmc {

enum class System { kTheodolite = 1, kGyrocompass = 2 };

inline int system_number(System s) { return static_cast<int>(s); }
/// Parses "1" or "2"; throws InputError naming `field` otherwise.
System parse_system(std::string_view text, std::string_view field = "system");

enum class Fidelity { kPaper, kLinear, kTruth };

std::string_view to_string(Fidelity f);
/// Parses "paper", "linear" or "truth"; throws InputError naming `field`.
Fidelity parse_fidelity(std::string_view text, std::string_view field = "fidelity");

}  // namespace insmc
