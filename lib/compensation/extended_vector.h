#pragma once
/// The extended parameter vector z of a compensated run: the uncertainties
/// x, the fresh per-alignment draws of a realignment, and what the test run
/// and the alignment phase produced (estimates and measurements). After a
/// compensation scheme the position error is a linear map of z; the
/// estimates themselves come from the simulated, quantized data of each
/// sample (never from an assumed distribution).
#include <Eigen/Core>

#include "lib/uncertainty/uncertainty_vector.h"

namespace insmc {
namespace ez {
inline constexpr int kX = 0;                                ///< x, the catalogue's uncertainties (ux::)
inline constexpr int kRealignZeta = ux::kDim;               ///< ζ_r of the realignment [rad] (3)
inline constexpr int kRealignBias = kRealignZeta + 3;       ///< ∂f_r of the realignment [m/s²] (2)
inline constexpr int kRealignVelocity = kRealignBias + 2;   ///< (u)V at the new switch-over [m/s] (3)
inline constexpr int kU2 = kRealignVelocity + 3;            ///< Û2 from position data (4.8b) (3)
inline constexpr int kU3 = kU2 + 3;                         ///< Û3 from position data (4.8c) (3)
inline constexpr int kU3Accel = kU3 + 3;                    ///< Û3 from the accelerometer data, slope of (5.12) (3)
inline constexpr int kDfT = kU3Accel + 3;                   ///< filtered Δf̂(T) of (5.10) [m/s²] (3)
inline constexpr int kTorquerCommands = kDfT + 3;           ///< measured alignment torquer commands ω_c (5.14) [rad/s] (3)
inline constexpr int kAlignAccel = kTorquerCommands + 3;    ///< measured alignment accelerometer outputs Δf_m (5.19) [m/s²] (3)
inline constexpr int kWiggleAtT = kAlignAccel + 3;          ///< velocity wiggle at T seen by the resets of 5.2/5.3 [m/s] (3)
inline constexpr int kDim = kWiggleAtT + 3;
}  // namespace ez

using ExtendedVector = Eigen::Matrix<double, ez::kDim, 1>;
using ExtendedMap = Eigen::Matrix<double, 3, ez::kDim>;

/// Catalogue slots that a realignment draws anew, paired with their z slots.
struct RealignedSlot {
  int x_index, z_index;
};
inline constexpr RealignedSlot kRealignedSlots[] = {
    {ux::kMisalignAlign + 0, ez::kRealignZeta + 0},   {ux::kMisalignAlign + 1, ez::kRealignZeta + 1},
    {ux::kMisalignAlign + 2, ez::kRealignZeta + 2},   {ux::kBiasChangeAlign + 0, ez::kRealignBias + 0},
    {ux::kBiasChangeAlign + 1, ez::kRealignBias + 1}, {ux::kInitialVelocity + 0, ez::kRealignVelocity + 0},
    {ux::kInitialVelocity + 1, ez::kRealignVelocity + 1}, {ux::kInitialVelocity + 2, ez::kRealignVelocity + 2},
};

}  // namespace insmc
