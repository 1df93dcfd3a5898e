#pragma once
/// What several candidates share: their parameter grids, noise added to the
/// f rows, deterministic signatures through the run's response (response.h)
/// and the specific force at rest the design effects are driven by.
#include <Eigen/Dense>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "lib/common/model_options.h"
#include "lib/units/physical_range.h"
#include "lib/units/units.h"
#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/runs/model/response.h"

namespace insmc::gap::candidates {

inline constexpr double kUg = 1e-6 * kGravityMps2;  // µg in m/s²

std::vector<double> scaled(std::initializer_list<double> values, double unit);

/// lo, lo·r, lo·r², … up to hi (within 1 %), r = 10^(1/4), × unit: the same
/// relative step (×1.78) for every scale parameter, so no candidate is
/// favoured by a grid that happens to hold the data's value.
std::vector<double> log_grid(double lo, double hi, double unit);

/// A parameter searched on `grid` (least G) and between the physical limits
/// [lower_si, upper_si] (maximum likelihood); `why`: where the limits come from.
CandidateParameter searched(std::string name, Dimension dimension, std::vector<double> grid, double lower_si,
                            double upper_si, std::string why);

/// An amplitude covering magnitudes up to `largest_si`, and why that far.
CandidateParameter amplitude(std::string name, Dimension dimension, double largest_si, std::string why);

/// The time of the layout's last row [s].
double layout_end(const runs::Layout& layout);

/// Noise added to the f rows (per axis weight) [ (m/s²)² ].
Eigen::VectorXd f_noise(const LayoutContext& ctx, const Eigen::Vector3d& var);

/// Noise added to the f rows by a platform angle of variance angle_var_rad2
/// + growth_rad2ps × t about each axis, through the specific force of each
/// row's time: the platform is space-stabilized, so gravity turns in it with
/// the earth and reaches the vertical accelerometer as well [ (m/s²)² ].
Eigen::VectorXd tilt_f_noise(const LayoutContext& ctx, double angle_var_rad2, double growth_rad2ps = 0.0);

/// Columns of a deterministic signature with amplitude prior params (one
/// column per axis unless `shared`).
Eigen::MatrixXd signature_columns(const LayoutContext& ctx, const std::string& key, int columns,
                                  const std::function<void(double, runs::Columns3&, runs::Columns3&)>& at);

/// f^{a'}(t) = −C(t) g_e, the specific force at rest in a' (3.24).
Eigen::Vector3d specific_force(double t, const ModelOptions& m);

}  // namespace insmc::gap::candidates
