#include "lib/alignment/alignment_loops.h"

#include <cmath>
#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/units/physical_range.h"

namespace insmc {
namespace {

using State = Eigen::Matrix<double, 6, 1>;  // C (3), then the filter states (3)

/// Constant inputs of the loops, from x (2.9), (2.13): the level signals
/// without disturbance and the drifts.
struct Inputs {
  double s1 = 0, s2 = 0, s3 = 0;  ///< δf_y/g + η + V01/g;  δf_x/g − ξ + V02/g;  … + V03/g (system 2)
  double azimuth_target = 0;      ///< (u)ψ + V03 (system 1)
  Vec3 drift = Vec3::Zero();      ///< ω_do
};

Inputs inputs_of(System system, const ModelOptions& m, const UncertaintyVector& x) {
  const double g = m.gravity_mps2, w = m.earth_rate_radps, cL = std::cos(m.latitude_rad);
  const Vec3 zeta_c = x.segment<3>(uncertainty_slot::kMisalignConst);
  Inputs in;
  in.drift = x.segment<3>(uncertainty_slot::kGyroDrift);
  const double dfx = x[uncertainty_slot::kAccelBias + 0] / g - x[uncertainty_slot::kDeflection + 0];
  in.s1 = x[uncertainty_slot::kAccelBias + 1] / g + x[uncertainty_slot::kDeflection + 1] + zeta_c.x();  // V01/g = ζ_cx (2.11a), (2.15a)
  if (system == System::kTheodolite) {
    in.s2 = dfx - zeta_c.y();  // V02/g = −ζ_cy (2.11a)
    in.azimuth_target = x[uncertainty_slot::kTheodolite] + zeta_c.z();  // V03 = ζ_cz
  } else {
    const double f2 = m.gyrocompass_f2_ratio * w;
    in.s3 = dfx - zeta_c.y();                              // V03/g = −ζ_cy (2.15a)
    in.s2 = dfx - zeta_c.y() + zeta_c.z() * w * cL / f2;   // V02/g = V03/g + ζ_cz ω_ie cos L0/F2(0)
  }
  return in;
}

struct Loops {
  System system;
  double w, sL, cL, g, tau;
  double f_level, f_azimuth;  // system 1: F(0), F_T(0) (inf allowed); system 2: K1, F2(0)
  double k3, t1, t3;
  Inputs in;
  const std::function<Vec3(double)>* disturbance;

  /// ω_c (less the earth-rate command) and Ċ, filter derivatives.
  void evaluate(double t, const State& y, Vec3& command, State& dy) const {
    const Vec3 r = (disturbance && *disturbance) ? Vec3((*disturbance)(t) / g) : Vec3::Zero();
    const Vec3 c = y.head<3>();
    const double e1 = in.s1 + r.y() - c.x();
    const double e2 = -(in.s2 + r.x() + c.y());
    if (system == System::kTheodolite) {
      command.x() = y[3];  // F1 output (low pass)
      command.y() = y[4];  // F2 output
      command.z() = std::isinf(f_azimuth) ? w * cL * c.y() - in.drift.z() : f_azimuth * (in.azimuth_target - c.z());
      dy[3] = (f_level * e1 - y[3]) / tau;
      dy[4] = (f_level * e2 - y[4]) / tau;
      dy[5] = 0.0;
    } else {
      const double e3 = -(in.s3 + r.x() + c.y());
      command.x() = f_level * (e1 + y[3] / t1);  // F1: proportional plus integral
      command.y() = y[4];                         // F2: low pass
      command.z() = k3 * (e3 + y[5] / t3);        // F3: proportional plus integral
      dy[3] = e1;
      dy[4] = (f_azimuth * e2 - y[4]) / tau;
      dy[5] = e3;
    }
    // (2.9)/(2.13): p C = ω_c − (coupling through ω_in) + ω_do.
    dy[0] = command.x() - w * sL * c.y() + in.drift.x();
    dy[1] = command.y() + w * sL * c.x() + w * cL * c.z() + in.drift.y();
    dy[2] = command.z() - w * cL * c.y() + in.drift.z();
  }
};

}  // namespace

void validate(const AlignmentLoopSettings& s) {
  // Loop time constants and averaging from a tenth of a second to six hours;
  // the fine alignment itself up to six hours (the loops settle in minutes).
  constexpr PhysicalRange kTime{0.1, 6 * 3600.0};
  require_in_range("--alignment-time", s.duration_s, Dimension::kTime, kTime);
  require_in_range("alignment level_filter_s", s.level_filter_s, Dimension::kTime, kTime);
  require_in_range("alignment level_integral_s", s.level_integral_s, Dimension::kTime, kTime);
  require_in_range("--alignment-average", s.average_s, Dimension::kTime, kTime);
  require_in_range("alignment step_s", s.step_s, Dimension::kTime, {0.0, 5.0, true});
  // A coarse alignment leaves milliradians; 0.1 rad keeps the loops' small-angle model.
  for (int k = 0; k < 3; ++k)
    require_in_range("--coarse-misalignment", s.initial_misalignment_rad[k], Dimension::kAngle,
                     {-magnitude_limit(Dimension::kAngle), magnitude_limit(Dimension::kAngle)});
}

AlignmentLoopRun simulate_alignment_loops(System system, const ModelOptions& m, const AlignmentLoopSettings& s,
                                          const UncertaintyVector& x,
                                          const std::function<Vec3(double)>& disturbance) {
  validate(s);
  const double w = m.earth_rate_radps;
  const double cL = std::cos(m.latitude_rad);
  // System 2's F3: the azimuth loop's triple pole at p0 = F2(0)/3 (header).
  const double p0 = m.gyrocompass_f2_ratio * w / 3.0;
  Loops loops{system, w, std::sin(m.latitude_rad), cL, m.gravity_mps2, s.level_filter_s,
              0.0, 0.0, 3.0 * p0 * p0 / (w * cL), s.level_integral_s, 3.0 / p0,
              inputs_of(system, m, x), &disturbance};
  if (system == System::kTheodolite) {
    loops.f_level = m.leveling_gain_ratio * w;
    loops.f_azimuth = m.azimuth_gain_ratio * w;
  } else {
    loops.f_level = m.leveling_gain_ratio * w;
    loops.f_azimuth = m.gyrocompass_f2_ratio * w;
  }
  State y = State::Zero();
  y.head<3>() = s.initial_misalignment_rad;
  if (system == System::kTheodolite && std::isinf(loops.f_azimuth)) y[2] = loops.in.azimuth_target;  // held by the theodolite
  const int steps = std::max(1, static_cast<int>(std::ceil(s.duration_s / s.step_s - 1e-9)));
  const double h = s.duration_s / steps, t0 = -s.duration_s;
  const double window_start = -std::min(s.average_s, s.duration_s);
  Vec3 command_sum = Vec3::Zero(), c_sum = Vec3::Zero(), r_sum = Vec3::Zero();
  double weight_sum = 0.0;
  State k1, k2, k3, k4;
  Vec3 cmd, cmd_end;
  const auto accumulate = [&](double t, const State& state, double weight) {
    State unused;
    loops.evaluate(t, state, cmd_end, unused);
    command_sum += weight * cmd_end;
    c_sum += weight * state.head<3>();
    if (disturbance) r_sum += weight * disturbance(t);
    weight_sum += weight;
  };
  for (int i = 0; i < steps; ++i) {
    const double t = t0 + i * h;
    if (t >= window_start - 1e-9) accumulate(t, y, 0.5 * h);  // trapezoid: the step's start …
    loops.evaluate(t, y, cmd, k1);
    loops.evaluate(t + 0.5 * h, y + 0.5 * h * k1, cmd, k2);
    loops.evaluate(t + 0.5 * h, y + 0.5 * h * k2, cmd, k3);
    loops.evaluate(t + h, y + h * k3, cmd, k4);
    y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (t >= window_start - 1e-9) accumulate(t + h, y, 0.5 * h);  // … and its end
  }
  AlignmentLoopRun run;
  run.misalignment_rad = y.head<3>();
  run.mean_command_radps = command_sum / weight_sum;
  const Vec3 c = c_sum / weight_sum, r = r_sum / weight_sum;
  const double g = m.gravity_mps2;
  // (5.18), (5.19): x g C_y − ξ g + δf_x; y −g C_x + η g + δf_y; z δf_z − g a_z + δg (δg/g = −3 δh/r0).
  run.mean_accel_output_mps2 = Vec3(g * c.y() - g * x[uncertainty_slot::kDeflection + 0] + x[uncertainty_slot::kAccelBias + 0] + r.x(),
                                    -g * c.x() + g * x[uncertainty_slot::kDeflection + 1] + x[uncertainty_slot::kAccelBias + 1] + r.y(),
                                    x[uncertainty_slot::kAccelBias + 2] - g * x[uncertainty_slot::kAccelScale + 2] -
                                        3.0 * g * x[uncertainty_slot::kAltitudeError] / m.radius_m);
  return run;
}

}  // namespace insmc
