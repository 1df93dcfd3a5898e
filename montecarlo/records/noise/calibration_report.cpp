#include "montecarlo/records/noise/calibration_report.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "lib/units/units.h"
#include "montecarlo/report/csv.h"

namespace insmc::noise {
namespace {

using calibration::CalibratedParameter;
using calibration::ParameterKind;

/// SI to the unit engineers quote: (factor, unit).
std::pair<double, const char*> quoted_unit(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::kAccelBias: return {1 / kMgToMps2, "mg"};
    case ParameterKind::kGyroBias: return {1 / kDegphToRadps, "deg/h"};
    case ParameterKind::kScaleFactor: return {1e6, "ppm"};
    case ParameterKind::kMisalignment: return {1e3, "mrad"};
    case ParameterKind::kGSensitivity: return {kGravityMps2 / kDegphToRadps, "deg/h/g"};
  }
  return {1, ""};
}

const char* sensor_of(ParameterKind kind, const std::string& name) {
  return kind == ParameterKind::kAccelBias || name.rfind("accel_", 0) == 0 ? "accelerometer" : "gyro";
}

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : "-"; }

std::string separable_text(const CalibratedParameter& p) {
  if (!std::isfinite(p.vif) || !std::isfinite(p.sigma_si)) return "**no** (not determined)";
  return p.separable() ? fmt::format("yes ({:.3g})", p.vif) : fmt::format("**no** ({:.3g})", p.vif);
}

std::string fit_rows(const calibration::FitSummary& fit) {
  std::string md;
  for (const CalibratedParameter& p : fit.parameters) {
    const auto [factor, unit] = quoted_unit(p.kind);
    md += fmt::format("| {} | {} | {} | [{}, {}] | {} | {} |\n", sensor_of(p.kind, p.name), p.name,
                      number(p.value_si * factor), number(p.lo_si * factor), number(p.hi_si * factor), unit,
                      separable_text(p));
  }
  return md;
}

std::string one_recording(const RecordingCalibration& rc, double confidence) {
  const calibration::MultipositionCalibration& c = rc.result;
  std::string md = fmt::format("\n## Multi-position calibration: {}\n\n", rc.recording);
  md += fmt::format(
      "{} still attitudes in {} orientations (mean specific force more than 5° apart), gravity {:.6g} m/s² the only "
      "reference. Model and method: docs/noise.md §6, (C.1)-(C.4). The body frame is the accelerometer triad's own "
      "(z along its z axis, y in its y-z plane); scale factors are relative to the declared column units (a reading "
      "of 1 unit is 1 + s units). Intervals at {:g} % (Student's t on the residual scatter); a parameter is separable "
      "when its variance inflation is at most {:g}.\n\n",
      c.segments.size(), c.orientations, rc.gravity_mps2, 100 * confidence, calibration::kMaxSeparableVif);
  md += "| sensor | parameter | value | interval | unit | separable (VIF) |\n|---|---|---:|---|---|---|\n";
  md += fit_rows(c.accel) + fit_rows(c.gyro_static) + fit_rows(c.gyro_turns);
  md += "\nThe gyro biases and g-sensitivities are in the declared gyro units (the model removes them before the "
        "scale factor, (C.4)): in calibrated units each row is 1 + s of its gyro axis times larger.\n";
  if (!c.gyro_turns.fitted) md += fmt::format("\nGyro scale factors and misalignments not fitted: {}.\n", c.gyro_turns.why_not);
  md += fmt::format(
      "\nResidual scatter: |f| − g at rest (C.2) {:.3g} mg over {} attitudes; gyro means at rest (C.3) up to {:.3g} "
      "deg/h",
      c.accel.residual_rms_si / kMgToMps2, c.accel.residuals, c.gyro_static.residual_rms_si / kDegphToRadps);
  if (c.gyro_turns.fitted)
    md += fmt::format("; gravity direction after each turn (C.4) {:.3g} mrad over {} turns",
                      1e3 * c.gyro_turns.residual_rms_si, c.gyro_turns.residuals / 3);
  md += ".\n\ng-sensitivity, F-test of each gyro axis's row of G = 0 in (C.3) (the earth rate's vertical part "
        "is in G too, below): ";
  for (std::size_t k = 0; k < c.g_sensitivity_p.size(); ++k)
    md += fmt::format("{}{} p = {:.2g}", k ? ", " : "", "xyz"[k], c.g_sensitivity_p[k]);
  md += fmt::format(
      ".\n\nWhat stays unseparated: the gyro means at rest hold the earth rate's projection as well (up to {:.3g} "
      "deg/h): its vertical part, Ω sin L along gravity, enters the diagonal of G (up to {:.3g} deg/h/g) and its "
      "horizontal part, which turns with the heading, adds to the scatter of (C.3); the triad's heading and the "
      "rotation of the whole body frame are not seen by gravity at all.\n",
      kEarthRateRadps / kDegphToRadps, kEarthRateRadps / kDegphToRadps);
  return md;
}

}  // namespace

bool any_calibrated(const std::vector<RecordingCalibration>& calibrations) {
  for (const RecordingCalibration& rc : calibrations)
    if (rc.result.accel.fitted) return true;
  return false;
}

std::string calibration_markdown(const std::vector<RecordingCalibration>& calibrations, double confidence) {
  std::string md;
  for (const RecordingCalibration& rc : calibrations)
    if (rc.result.accel.fitted) md += one_recording(rc, confidence);
  return md;
}

std::string calibration_csv(const std::vector<RecordingCalibration>& calibrations) {
  mc::Table t({"recording", "sensor", "parameter", "value", "lo", "hi", "unit", "value_si", "sigma_si", "lo_si",
               "hi_si", "vif", "separable"});
  for (const RecordingCalibration& rc : calibrations)
    for (const auto* fit : {&rc.result.accel, &rc.result.gyro_static, &rc.result.gyro_turns})
      for (const CalibratedParameter& p : fit->parameters) {
        const auto [factor, unit] = quoted_unit(p.kind);
        t.add_row({rc.recording, sensor_of(p.kind, p.name), p.name, mc::format_number(p.value_si * factor),
                   mc::format_number(p.lo_si * factor), mc::format_number(p.hi_si * factor), unit,
                   mc::format_number(p.value_si), mc::format_number(p.sigma_si), mc::format_number(p.lo_si),
                   mc::format_number(p.hi_si), mc::format_number(p.vif), p.separable() ? "yes" : "no"});
      }
  return mc::render_csv(t);
}

mc::Json calibration_json(const std::vector<RecordingCalibration>& calibrations) {
  mc::Json out = mc::Json::array();
  for (const RecordingCalibration& rc : calibrations) {
    const calibration::MultipositionCalibration& c = rc.result;
    mc::Json j = mc::Json::object();
    j["recording"] = rc.recording;
    j["still_attitudes"] = c.segments.size();
    j["orientations"] = c.orientations;
    j["gravity_mps2"] = rc.gravity_mps2;
    j["fitted"] = c.accel.fitted;
    if (!c.accel.fitted) j["why_not"] = c.accel.why_not;
    mc::Json params = mc::Json::array();
    for (const auto* fit : {&c.accel, &c.gyro_static, &c.gyro_turns})
      for (const CalibratedParameter& p : fit->parameters) {
        mc::Json q = mc::Json::object();
        q["name"] = p.name;
        q["sensor"] = sensor_of(p.kind, p.name);
        q["value_si"] = p.value_si;
        q["sigma_si"] = p.sigma_si;
        q["lo_si"] = p.lo_si;
        q["hi_si"] = p.hi_si;
        q["vif"] = p.vif;
        q["separable"] = p.separable();
        params.push_back(std::move(q));
      }
    j["parameters"] = std::move(params);
    if (c.accel.fitted) {
      mc::Json r = mc::Json::object();
      r["accel_mps2"] = c.accel.residual_rms_si;
      r["gyro_at_rest_radps"] = c.gyro_static.residual_rms_si;
      r["gyro_turns_rad"] = c.gyro_turns.residual_rms_si;
      j["residual_rms"] = std::move(r);
      mc::Json p = mc::Json::array();
      for (double v : c.g_sensitivity_p) p.push_back(v);
      j["g_sensitivity_p"] = std::move(p);
    }
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace insmc::noise
