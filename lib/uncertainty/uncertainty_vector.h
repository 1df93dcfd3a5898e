#pragma once
/// The flat view of one sample's uncertainties: a fixed-size vector of the 43
/// catalogue parameters (Table 3.1 and chapter 2, then the measurement errors
/// the compensation schemes of chapter 5 rely on), SI units, in the order
/// below. The catalogue (catalogue.h) names each slot; everything else
/// indexes through these constants.
#include <Eigen/Core>

namespace insmc {
namespace uncertainty_slot {
inline constexpr int kAccelBias = 0;        ///< δf_x,y,z [m/s²], alignment and navigation (3)
inline constexpr int kAccelScale = 3;       ///< a_x,y,z, dimensionless (3)
inline constexpr int kBiasChangeConst = 6;  ///< ∂f_cx,cy [m/s²], constant part of the switch-over step (2)
inline constexpr int kBiasChangeAlign = 8;  ///< ∂f_rx,ry [m/s²], drawn anew at each alignment (2)
inline constexpr int kGyroDrift = 10;       ///< ω_do,x,y,z [rad/s], level-platform drift (3)
inline constexpr int kGyroMuDrift = 13;     ///< ω_MU,x,y,z [rad/s] of (3.13a) (3)
inline constexpr int kGyroMuyDrift = 16;    ///< g·MUY_x,y,z [rad/s] (3)
inline constexpr int kMisalignConst = 19;   ///< ζ_cx,cy,cz [rad], alignment electronics (3)
inline constexpr int kMisalignAlign = 22;   ///< ζ_rx,ry,rz [rad], drawn anew at each alignment (3)
inline constexpr int kTheodolite = 25;      ///< (u)ψ [rad], system 1 only (1)
inline constexpr int kDeflection = 26;      ///< ξ, η [rad] (2)
inline constexpr int kInitialVelocity = 28; ///< (u)V_x,y,z [m/s] at switch-over (3)
inline constexpr int kLatitudeError = 31;   ///< δL_0 [rad] (1)
inline constexpr int kAltitudeError = 32;   ///< δh [m] (1)
// The schemes' own measurement errors (chapter 5): zero effect on an
// uncompensated run, each acting only through the scheme that relies on it
// (catalogue.h's kSchemeErrorGroups says which slots they are).
inline constexpr int kAlignDriftError = 33;    ///< ω_ie E4 of (5.15), (5.15a): 5.4's drift-estimate error [rad/s] (3)
inline constexpr int kResetPositionError = 36; ///< error of the position reset at T, points 5 of (5.8), (5.11) [m] (3)
inline constexpr int kResetVelocityError = 39; ///< error of the velocity reset at T, point 6 of (5.8), (5.11) [m/s] (3)
/// δψ_r: the change of system 1's theodolite azimuth at a realignment of
/// 5.1.x (re-sighting), on top of (u)ψ which the realignment keeps (1)
inline constexpr int kRealignAzimuthError = 42;
inline constexpr int kDim = 43;
}  // namespace uncertainty_slot

using UncertaintyVector = Eigen::Matrix<double, uncertainty_slot::kDim, 1>;
/// Linear map from the uncertainties to a 3-vector (e.g. S(t), U2..U5).
using Sensitivity3 = Eigen::Matrix<double, 3, uncertainty_slot::kDim>;
/// Covariance of the uncertainties.
using UncertaintyCovariance = Eigen::Matrix<double, uncertainty_slot::kDim, uncertainty_slot::kDim>;

}  // namespace insmc
