#pragma once
/// The flat view of one sample's uncertainties: a fixed-size vector of the 33
/// catalogue parameters (Table 3.1 and chapter 2), SI units, in the order
/// below. The catalogue (catalogue.h) names each slot; everything else
/// indexes through these constants.
#include <Eigen/Core>

namespace insmc {
namespace ux {
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
inline constexpr int kDim = 33;
}  // namespace ux

using UncertaintyVector = Eigen::Matrix<double, ux::kDim, 1>;
/// Linear map from the uncertainties to a 3-vector (e.g. S(t), U2..U5).
using Sensitivity3 = Eigen::Matrix<double, 3, ux::kDim>;
/// Covariance of the uncertainties.
using UncertaintyCovariance = Eigen::Matrix<double, ux::kDim, ux::kDim>;

}  // namespace insmc
