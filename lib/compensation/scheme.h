#pragma once
/// The compensation schemes of chapter 5, each with the clock its results
/// are reported on (clock_of).
#include <string_view>
#include <vector>

namespace insmc {

enum class Scheme {
  kNone,      ///< uncompensated (3.29)
  k5_1_1,     ///< Û2 at point 2, Û3 through integrators to point 2, realign (5.2)–(5.4)
  k5_1_2,     ///< Û2 at point 2, Û3 to the gyro torquers, realign (5.5)–(5.7)
  kCombined,  ///< 5.1.1 with 5.1.2: torquers where they help, integrators for the rest (end of 5.1.2)
  k5_2,       ///< position data, no realignment, position and velocity reset at T (5.8)–(5.9)
  k5_3,       ///< position and filtered accelerometer data, no realignment (5.10)–(5.12)
  k5_4,       ///< alignment-phase data only: torquer commands and accelerometer outputs (5.13)–(5.21)
};

/// "none", "5.1.1", "5.1.2", "combined", "5.2", "5.3", "5.4": the one
/// spelling used in options and files.
std::string_view to_string(Scheme s);
/// Parses one name; throws InputError naming `field` and listing the schemes.
Scheme parse_scheme(std::string_view text, std::string_view field = "--scheme");
/// Every scheme, in report order.
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
