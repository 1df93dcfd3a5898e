#pragma once
/// A compensation scheme of chapter 5: a handle on its definition in the
/// registry (schemes/registry.cpp, one file per scheme in schemes/). Every
/// trait below is the definition's; nothing outside schemes/ decides what a
/// scheme does by its name.
#include <compare>
#include <string_view>
#include <vector>

namespace insmc {

struct SchemeDefinition;

class Scheme {
 public:
  /// The report's schemes, in report order (the registry's first entries).
  static const Scheme kNone;      ///< uncompensated (3.29)
  static const Scheme k5_1_1;     ///< Û2 at point 2, Û3 through integrators to point 2, realign (5.2)–(5.4)
  static const Scheme k5_1_2;     ///< Û2 at point 2, Û3 to the gyro torquers, realign (5.5)–(5.7)
  static const Scheme kCombined;  ///< 5.1.1 with 5.1.2: torquers where they help, integrators for the rest
  static const Scheme k5_2;       ///< position data, no realignment, position and velocity reset at T (5.8)–(5.9)
  static const Scheme k5_3;       ///< position and filtered accelerometer data, no realignment (5.10)–(5.12)
  static const Scheme k5_4;       ///< alignment-phase data only: torquer commands and accelerometer outputs (5.13)–(5.21)

  constexpr Scheme() = default;
  /// The registry's entry `index` (checked by definition()).
  constexpr explicit Scheme(int index) : index_(index) {}
  constexpr int index() const { return index_; }
  /// Registry order: the report's order for its schemes.
  constexpr auto operator<=>(const Scheme&) const = default;
  const SchemeDefinition& definition() const;

 private:
  int index_ = 0;
};

inline constexpr Scheme Scheme::kNone{0};
inline constexpr Scheme Scheme::k5_1_1{1};
inline constexpr Scheme Scheme::k5_1_2{2};
inline constexpr Scheme Scheme::kCombined{3};
inline constexpr Scheme Scheme::k5_2{4};
inline constexpr Scheme Scheme::k5_3{5};
inline constexpr Scheme Scheme::k5_4{6};

/// Adds a scheme to the registry (a scheme defined outside this library,
/// e.g. in a test) and returns its handle. Call before any study starts
/// (the registry is not locked); throws std::logic_error on a name in use.
/// `definition` must outlive every use of the handle.
Scheme register_scheme(const SchemeDefinition& definition);

/// "none", "5.1.1", "5.1.2", "combined", "5.2", "5.3", "5.4": the one
/// spelling used in options and files.
std::string_view to_string(Scheme s);
/// Parses one name; throws InputError naming `field` and listing the schemes.
Scheme parse_scheme(std::string_view text, std::string_view field = "--scheme");
/// Every scheme in the registry, in its order (the report's first).
std::vector<Scheme> all_schemes();

/// Where t = 0 is for a scheme's results: "switchover" (none, 5.4),
/// "realignment" (5.1.1, 5.1.2, combined: the new switch-over) or
/// "test_end" (5.2, 5.3: t' = t − T).
std::string_view clock_of(Scheme s);

bool realigns(Scheme s);
bool resets_at_test_end(Scheme s);
/// Needs the preflight test run (all but none and 5.4).
bool uses_test_run(Scheme s);
/// Needs the alignment phase's torquer commands and accelerometer outputs
/// (5.4: (5.14), (5.19)).
bool uses_alignment_data(Scheme s);

/// Where the scheme's clock (clock_of) starts, in time since the first
/// switch-over: the second switch-over `nav_start_s` after a realignment,
/// the test's end T after the resets, else 0.
double clock_start_s(Scheme s, double test_duration_s, double nav_start_s);
/// From the first switch-over until the vehicle may fly: T plus the
/// realignment where there is one, T with the resets, 0 for none and 5.4.
double ready_time_s(Scheme s, double test_duration_s, double realignment_duration_s);
/// Time since the switch-over of the platform frame a' the scheme's errors
/// are expressed in, at t = 0 on its clock: T after the resets (the same
/// navigation goes on), 0 otherwise (a realignment switches over anew).
double frame_time_offset_s(Scheme s, double test_duration_s);

}  // namespace insmc
