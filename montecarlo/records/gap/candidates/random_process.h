#pragma once
/// Random processes as candidates (instabilities, random walks): a process
/// is carried by its values on knots plus the first bridge mode between
/// them as columns of the run model, the faster rest as noise on the f rows.
#include "montecarlo/records/gap/candidates/candidates.h"

namespace insmc::gap::candidates {

/// Knot spacing of the random-process bases [s]: random walks at the
/// smallest, Gauss–Markov processes a correlation time apart within these
/// bounds; between knots the bridge's first mode is a column and the faster
/// part enters the f rows as noise.
inline constexpr double kKnotSpacingS = 420.0;
inline constexpr double kMinKnotSpacingS = 150.0;
/// At most this many knots per run: a run of the report's length (15 min
/// test run, 90 min navigation: 42 knots at 150 s) keeps the spacings above;
/// a longer one gets knots further apart, so that the model's columns, and
/// its cost, stop growing with the run's duration (the bridge modes and the
/// f noise carry the finer structure, and the null is simulated through
/// the same model, so the test keeps its level).
inline constexpr int kMaxKnots = 48;

/// What the process is: an accelerometer error, a platform angle, a gyro
/// rate (the angle is its integral) or a velocity (the accelerometer error
/// is its derivative).
enum class Drive { kAccel, kAngle, kRate, kVelocity };

/// A random process on the knots with σ = params[0], τ = params[1].
runs::Extension process_extension(const LayoutContext& ctx, Drive drive, double sigma, double tau);

}  // namespace insmc::gap::candidates
