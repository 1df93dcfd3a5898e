#pragma once
/// The linear level's response of a run's observation rows (layout.h) to
/// the uncertainties x and to other inputs (lib/propagation/linear_model.h):
/// every observation is a linear function of its causes,
///   f row at t:  (1/τ) ∫_{t−τ}^{t} u(s) ds     (4.2): Δf^a equals the forcing u,
///   r row at t:  δr(t) of δr̈ + ω_s² δr = u(t)  (3.24),
/// with, for an input accelerometer error a(t) and platform angle θ(t)
/// (rotation of the platform against a', both beyond x),
///   u(t) = a(t) − (C(t) g_e) × θ(t)           (3.24): a tilt θ is seen like D(t),
/// and zero initial conditions (they start at switch-over).
#include <Eigen/Core>
#include <functional>

#include "montecarlo/records/runs/files/layout.h"

namespace insmc::runs {

using Columns3 = Eigen::Matrix<double, 3, Eigen::Dynamic>;

/// An input with `columns` unit components: fills accel (3 × columns, m/s²)
/// and angle (3 × columns, rad) at time t ≥ 0.
struct InputSignal {
  int columns = 0;
  std::function<void(double t_s, Columns3& accel_mps2, Columns3& angle_rad)> at;
  /// false: the f rows do not respond (for inputs whose effect on f is
  /// modelled as row noise instead, e.g. white accelerometer noise).
  bool f_responds = true;
};

/// Rows × 33: the observations per unit of each uncertainty (linear level),
/// uncompensated (the navigation rows after a scheme: scheme_rows.h).
Eigen::MatrixXd uncertainty_response(const Layout& layout, const RecordSite& site);

/// Rows × input.columns: the observations per unit of each input column.
/// After a reset (5.2, 5.3) the navigation rows start a zero state at T with
/// the input going on; after a realignment they are a new navigation on
/// their own clock with the input starting again (the same signature for a
/// design effect; a random process needs its own columns there:
/// Layout::restarted_part).
Eigen::MatrixXd input_response(const Layout& layout, const RecordSite& site, const InputSignal& input);

/// C(t) g_e: gravitation (down at t = 0) in a' at time t [m/s²] (3.24).
Eigen::Vector3d gravity_in_ap(double t_s, const ModelOptions& model);

}  // namespace insmc::runs
