#pragma once
/// The extended parameter vector z of a compensated run: the uncertainties
/// x, the fresh per-alignment draws of a realignment, and what the test run
/// and the alignment phase produced (estimates and measurements). After a
/// compensation scheme the position error is a linear map of z; the
/// estimates themselves come from the simulated, quantized data of each
/// sample (never from an assumed distribution).
#include <Eigen/Core>
#include <iterator>
#include <string_view>

#include "lib/uncertainty/uncertainty_vector.h"

namespace insmc {
/// One block of z after x: what it holds (as `run --replay` prints it),
/// its SI unit (empty: dimensionless) and its size.
struct ExtendedSlot {
  std::string_view name;
  std::string_view unit;
  int size;
};

namespace z_slot {
/// The slots after x, in z's order: the one list of them (the pipeline
/// writes each at its start below, `run --replay` prints them from here).
inline constexpr ExtendedSlot kSlots[] = {
    {"realignment zeta_r", "rad", 3},              ///< ζ_r of the realignment
    {"realignment bias change", "mps2", 2},        ///< ∂f_r of the realignment
    {"realignment velocity", "mps", 3},            ///< (u)V at the new switch-over
    {"U2 hat (position fit)", "", 3},              ///< Û2 from position data (4.8b)
    {"U3 hat (position fit)", "", 3},              ///< Û3 from position data (4.8c)
    {"U3 hat (accelerometer fit)", "", 3},         ///< Û3 from the accelerometer data, slope of (5.12)
    {"filtered delta f(T)", "mps2", 3},            ///< filtered Δf̂(T) of (5.10)
    {"alignment torquer commands", "radps", 3},    ///< measured alignment torquer commands ω_c (5.14)
    {"alignment accelerometer outputs", "mps2", 3},  ///< measured alignment accelerometer outputs Δf_m (5.19)
    {"velocity wiggle at T", "mps", 3},            ///< velocity wiggle at T seen by the resets of 5.2/5.3
};
inline constexpr int kSlotCount = static_cast<int>(std::size(kSlots));

/// Where slot `slot` of kSlots starts in z.
constexpr int slot_start(int slot) {
  int start = uncertainty_slot::kDim;
  for (int i = 0; i < slot; ++i) start += kSlots[i].size;
  return start;
}

inline constexpr int kX = 0;                           ///< x, the catalogue's uncertainties (uncertainty_slot::)
inline constexpr int kRealignZeta = slot_start(0);
inline constexpr int kRealignBias = slot_start(1);
inline constexpr int kRealignVelocity = slot_start(2);
inline constexpr int kU2 = slot_start(3);
inline constexpr int kU3 = slot_start(4);
inline constexpr int kU3Accel = slot_start(5);
inline constexpr int kDfT = slot_start(6);
inline constexpr int kTorquerCommands = slot_start(7);
inline constexpr int kAlignAccel = slot_start(8);
inline constexpr int kWiggleAtT = slot_start(9);
inline constexpr int kDim = slot_start(kSlotCount);
static_assert(kWiggleAtT + 3 == kDim, "every slot of kSlots has its start above");
}  // namespace z_slot

using ExtendedVector = Eigen::Matrix<double, z_slot::kDim, 1>;
using ExtendedMap = Eigen::Matrix<double, 3, z_slot::kDim>;

/// Catalogue slots that a realignment draws anew, paired with their z slots.
struct RealignedSlot {
  int x_index, z_index;
};
inline constexpr RealignedSlot kRealignedSlots[] = {
    {uncertainty_slot::kMisalignAlign + 0, z_slot::kRealignZeta + 0},   {uncertainty_slot::kMisalignAlign + 1, z_slot::kRealignZeta + 1},
    {uncertainty_slot::kMisalignAlign + 2, z_slot::kRealignZeta + 2},   {uncertainty_slot::kBiasChangeAlign + 0, z_slot::kRealignBias + 0},
    {uncertainty_slot::kBiasChangeAlign + 1, z_slot::kRealignBias + 1}, {uncertainty_slot::kInitialVelocity + 0, z_slot::kRealignVelocity + 0},
    {uncertainty_slot::kInitialVelocity + 1, z_slot::kRealignVelocity + 1}, {uncertainty_slot::kInitialVelocity + 2, z_slot::kRealignVelocity + 2},
};

}  // namespace insmc
