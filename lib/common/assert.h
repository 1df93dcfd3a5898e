#pragma once
/// Programmer and numerical invariants: INSMC_ASSERT(cond, "fmt {}", values...)
/// prints the formatted values and aborts. Never used for user input.
#include <cstdio>
#include <cstdlib>
#include <fmt/core.h>

#define INSMC_ASSERT(cond, ...)                                                    \
  do {                                                                             \
    if (!(cond)) {                                                                 \
      std::fprintf(stderr, "insmc: internal error at %s:%d: %s: %s\n", __FILE__,   \
                   __LINE__, #cond, fmt::format(__VA_ARGS__).c_str());             \
      std::abort();                                                                \
    }                                                                              \
  } while (false)
