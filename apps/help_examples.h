#pragma once
/// One or two commands per subcommand, printed at the end of its --help:
/// what a new user types first.
#include <span>
#include <string_view>

namespace insmc::app {

/// The examples of `subcommand` (empty for a name without any).
std::span<const std::string_view> help_examples(std::string_view subcommand);

}  // namespace insmc::app
