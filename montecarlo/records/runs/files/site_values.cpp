#include "montecarlo/records/runs/files/site_values.h"

#include <fmt/format.h>

#include "montecarlo/records/runs/files/record_lattice.h"

namespace insmc::runs {
namespace {

std::string lattice_reason(const LatticeFit& fit, const char* what, const char* unit) {
  switch (fit.kind) {
    case LatticeFit::Kind::kLattice:
      return fmt::format("the {} {} lie on a lattice of step {:.6g} {} ({} distinct multiples, within 1 % of a step)",
                         fit.values, what, fit.step, unit, fit.distinct_multiples);
    case LatticeFit::Kind::kContinuous:
      return fmt::format("the {} {} lie on no lattice of step from {:.3g} to {:.3g} {}", fit.values, what,
                         fit.finest_tried, fit.coarsest_tried, unit);
    case LatticeFit::Kind::kUndecided: break;
  }
  return fmt::format("only {} {}: too few to tell a lattice", fit.values, what);
}

}  // namespace

std::vector<SiteValue> complete_site(const RecordFile& file, RecordSite& site, double default_pulse_mps) {
  const RecordHeader& h = file.header;
  std::vector<SiteValue> out;
  out.push_back({"latitude_deg", h.latitude_deg(), "header", "stated"});
  out.push_back({"system", static_cast<double>(h.system() == System::kTheodolite ? 1 : 2), "header", "stated"});
  out.push_back({"test_duration_s", site.test_duration_s, "header", "stated"});
  if (h.filter_interval_s()) {
    out.push_back({"filter_interval_s", site.filter_interval_s, "header", "stated"});
  } else {
    const double spacing = median_f_spacing(file);
    site.filter_interval_s = spacing > 0 ? spacing : 10.0;
    out.push_back({"filter_interval_s", site.filter_interval_s, spacing > 0 ? "inferred" : "default",
                   spacing > 0 ? fmt::format("filter_interval_s absent: the spacing of the test run's f rows, {:g} s "
                                             "(their median, or where the time stamps jitter their mean over "
                                             "consecutive rows in the fewest digits within three standard errors; "
                                             "a window shorter than the spacing cannot be told from the rows)",
                                             spacing)
                               : "filter_interval_s absent and no f rows: 10 s assumed (no f row is modelled)"});
  }
  if (const std::optional<double> w = h.dv_pulse_mps()) {
    site.dv_pulse_mps = *w;
    out.push_back({"dv_pulse_mps", *w, "header", *w > 0 ? "stated" : "stated: continuous outputs"});
  } else {
    const LatticeFit fit = f_pulse_lattice(file, site.model, site.filter_interval_s);
    const std::string why = lattice_reason(fit, "test-run f increments (f τ plus the nominal's increment)", "m/s");
    if (fit.kind == LatticeFit::Kind::kLattice && !(fit.step >= kMinDvPulseMps && fit.step <= kMaxDvPulseMps)) {
      site.dv_pulse_mps = 0.0;
      out.push_back({"dv_pulse_mps", 0.0, "inferred",
                     fmt::format("dv_pulse_mps absent: {}, outside the pulse weights of record format v1 [{:g}, {:g}] "
                                 "m/s: continuous outputs assumed", why, kMinDvPulseMps, kMaxDvPulseMps)});
    } else if (fit.kind == LatticeFit::Kind::kLattice) {
      site.dv_pulse_mps = fit.step;
      out.push_back({"dv_pulse_mps", fit.step, "inferred", "dv_pulse_mps absent: " + why + ": pulses of that weight"});
    } else if (fit.kind == LatticeFit::Kind::kContinuous) {
      site.dv_pulse_mps = 0.0;
      out.push_back({"dv_pulse_mps", 0.0, "inferred", "dv_pulse_mps absent: " + why + ": continuous outputs assumed"});
    } else {
      site.dv_pulse_mps = default_pulse_mps;
      out.push_back({"dv_pulse_mps", default_pulse_mps, "default",
                     fmt::format("dv_pulse_mps absent: {}: the model's pulse weight {:.6g} m/s assumed", why,
                                 default_pulse_mps)});
    }
  }
  if (const std::optional<double> q = h.position_resolution_m()) {
    site.position_resolution_m = *q;
    out.push_back({"position_resolution_m", *q, "header", *q > 0 ? "stated" : "stated: exact"});
  } else {
    const LatticeFit fit = r_resolution_lattice(file, site.model);
    const std::string why = lattice_reason(fit, "test-run r values (r plus the true position, less the run's first)", "m");
    const bool lattice = fit.kind == LatticeFit::Kind::kLattice && fit.step >= kMinPositionResolutionM &&
                         fit.step <= kMaxPositionResolutionM;
    site.position_resolution_m = lattice ? fit.step : 0.0;
    out.push_back({"position_resolution_m", site.position_resolution_m,
                   fit.kind == LatticeFit::Kind::kUndecided ? "default" : "inferred",
                   "position_resolution_m absent: " + why +
                       (lattice ? ": a position computer of that resolution"
                                : ": exact positions assumed (resolution 0)")});
  }
  return out;
}

mc::Json site_values_json(const std::vector<SiteValue>& values) {
  mc::Json site = mc::Json::object();
  for (const SiteValue& v : values) {
    mc::Json e = mc::Json::object();
    e["value"] = v.value;
    e["source"] = v.source;
    e["reason"] = v.reason;
    site[v.key] = e;
  }
  return site;
}

}  // namespace insmc::runs
