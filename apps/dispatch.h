#pragma once
/// `insmc <subcommand> [options]`: the subcommand found by name and run,
/// and what every subcommand's failure becomes on stderr and in the exit
/// code: bad input (InputError, an option the parser refuses, memory the
/// input needs) one line and 2, a defect one line and 3. The list of
/// subcommands is apps/insmc.cpp's; a test adds its own (tests/cli/).
#include <cstdio>
#include <span>
#include <string_view>

#include "apps/subcommands.h"

namespace insmc::app {

struct Subcommand {
  std::string_view name;
  int (*run)(const Args&);
  std::string_view summary;  ///< one line in `insmc --help`
};

/// Runs argv[1] of `subcommands` with the rest of the arguments; --help,
/// --version and an unknown name as above.
int dispatch(std::span<const Subcommand> subcommands, int argc, const char* const* argv);

}  // namespace insmc::app
