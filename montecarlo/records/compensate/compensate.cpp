#include "montecarlo/records/compensate/compensate.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/preflight/test_run.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"
#include "montecarlo/records/compensate/exceedance.h"

namespace insmc::compensate {

void validate(const CompensateOptions& options) {
  if (!(options.flight_time_s > 0 && options.flight_time_s <= kMaxFlightTimeS))
    throw InputError("--flight-time", format_quantity(options.flight_time_s, Dimension::kTime), "must lie in (0, 12h]");
  if (!(options.risk > 0 && options.risk <= 0.5))
    throw InputError("--risk", fmt::format("{}", options.risk), "must lie in (0, 0.5]");
  require_in_range("--realignment-duration", options.realignment_duration_s, Dimension::kTime,
                   test_run_range::kRealignmentDuration);
  if (options.site_gravity_mps2)
    require_in_range("--site-gravity", *options.site_gravity_mps2, Dimension::kAcceleration, kSiteGravityRange,
                     "the specific force on the earth's surface: 9.78 to 9.84 m/s^2 at sea level, less at altitude");
}
namespace {

constexpr double kGridStepS = 180.0;

const UnitPositionError& at_time(const SchemePrediction& p, double t_s) {
  for (const UnitPositionError& e : p.envelope)
    if (std::abs(e.t_s - t_s) < 1e-6) return e;
  INSMC_ASSERT(false, "no envelope point at {} s", t_s);
  return p.envelope.front();
}

LimitCheck check_limit(const SchemePrediction& p, const PositionLimit& limit, double risk) {
  const UnitPositionError& e = at_time(p, limit.t_s);
  LimitCheck c;
  c.limit = limit;
  c.risk = risk;
  if (limit.component == PositionLimit::Component::kHorizontal) {
    c.rms_m = e.unit_horizontal_rms_m();
    c.probability = probability_outside_circle(e.horizontal_mean_m(), e.horizontal_covariance_m2(), limit.limit_m);
  } else {
    const int a = static_cast<int>(limit.component) - 1;
    c.rms_m = e.unit_rms_m(a);
    c.probability = probability_beyond(e.mean_m[a], e.covariance_m2(a, a), limit.limit_m);
  }
  return c;
}

/// Without limits: the least horizontal RMS at the flight time, with the
/// runner-up and its margin.
void choose_by_flight_time(UnitResult& u, const CompensateOptions& options) {
  std::vector<std::pair<double, std::size_t>> at_flight;
  for (std::size_t i = 0; i < u.schemes.size(); ++i)
    at_flight.emplace_back(at_time(u.schemes[i], options.flight_time_s).unit_horizontal_rms_m(), i);
  std::stable_sort(at_flight.begin(), at_flight.end());
  u.choice = SchemeChoice::kLeastRmsAtFlightTime;
  u.recommended = u.schemes[at_flight.front().second].scheme;
  u.recommended_rms_m = at_flight.front().first;
  if (at_flight.size() > 1) {
    u.runner_up = u.schemes[at_flight[1].second].scheme;
    u.margin_m = at_flight[1].first - at_flight.front().first;
  }
}

/// With limits: every scheme against every limit; among those meeting them
/// all, the one whose worst limit has the most margin (the largest ratio
/// limit / RMS: unlike P(exceed), it does not underflow to 0 for several
/// schemes at once); when none meets them, the one coming closest (least
/// worst P(exceed)), and no-go.
void choose_by_limits(UnitResult& u, const CompensateOptions& options) {
  for (const SchemePrediction& p : u.schemes) {
    SchemeAgainstLimits a;
    a.scheme = p.scheme;
    for (const PositionLimit& l : options.limits) a.checks.push_back(check_limit(p, l, options.risk));
    u.against_limits.push_back(std::move(a));
  }
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < u.against_limits.size(); ++i)
    if (u.against_limits[i].meets_every_limit() &&
        (!best || u.against_limits[i].worst().ratio() > u.against_limits[*best].worst().ratio()))
      best = i;
  u.choice = best ? SchemeChoice::kMostMarginOverLimits : SchemeChoice::kNoneMeetsTheLimits;
  if (!best) {
    best = 0;
    for (std::size_t i = 1; i < u.against_limits.size(); ++i)
      if (u.against_limits[i].worst_probability() < u.against_limits[*best].worst_probability()) best = i;
  }
  u.recommended = u.against_limits[*best].scheme;
  u.recommended_rms_m = at_time(u.schemes[*best], options.flight_time_s).unit_horizontal_rms_m();
  u.checks = u.against_limits[*best].checks;
  u.go = u.choice == SchemeChoice::kMostMarginOverLimits;
}

/// The scheme to use (docs/compensate.md, "The scheme to use"). Rows the
/// model does not describe leave nothing to rest a choice or a go on, with
/// or without limits: a bench script reads the exit code alone.
void choose_scheme(UnitResult& u, const CompensateOptions& options) {
  if (!u.fits_model()) {
    u.choice = SchemeChoice::kNotChosen;
    u.go = false;
    return;
  }
  if (options.limits.empty()) choose_by_flight_time(u, options);
  else choose_by_limits(u, options);
}

}  // namespace

bool SchemeAgainstLimits::meets_every_limit() const {
  return std::all_of(checks.begin(), checks.end(), [](const LimitCheck& c) { return c.within(); });
}

const LimitCheck& SchemeAgainstLimits::worst() const {
  INSMC_ASSERT(!checks.empty(), "no limit");
  return *std::min_element(checks.begin(), checks.end(),
                           [](const LimitCheck& a, const LimitCheck& b) { return a.ratio() < b.ratio(); });
}

double SchemeAgainstLimits::worst_probability() const {
  double p = 0.0;
  for (const LimitCheck& c : checks) p = std::max(p, c.probability);
  return p;
}

std::string_view to_string(PositionLimit::Component c) {
  switch (c) {
    case PositionLimit::Component::kHorizontal: return "horizontal";
    case PositionLimit::Component::kX: return "x";
    case PositionLimit::Component::kY: return "y";
    case PositionLimit::Component::kZ: return "z";
  }
  return "";
}

bool LimitCheck::within() const { return probability <= risk; }

namespace {

/// The times the report tabulates: 42, 63 and 84 min, the flight time and
/// the limits' times.
std::vector<double> report_times(const CompensateOptions& options) {
  std::vector<double> t = {42 * 60.0, 63 * 60.0, 84 * 60.0, options.flight_time_s};
  for (const PositionLimit& l : options.limits) t.push_back(l.t_s);
  return t;
}

}  // namespace

bool is_report_time(double t_s, const CompensateOptions& options) {
  const std::vector<double> times = report_times(options);
  return std::any_of(times.begin(), times.end(), [&](double t) { return std::abs(t - t_s) < 1e-6; });
}

namespace {

/// The envelope's times: every 3 min to the last report time, and the
/// report times themselves.
std::vector<double> envelope_times(const CompensateOptions& options) {
  std::vector<double> t = report_times(options);
  const double last = *std::max_element(t.begin(), t.end());
  for (int k = 1; k * kGridStepS <= last + 1e-9; ++k) t.push_back(k * kGridStepS);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return std::abs(a - b) < 1e-6; }), t.end());
  return t;
}

}  // namespace

CompensateResult compensate(const RecordFile& file, const CompensateOptions& options) {
  validate(options);
  INSMC_ASSERT(!options.schemes.empty(), "no scheme");
  CompensateResult out;
  out.records = read_unit_records(file, options.prior, options.run, options.site_gravity_mps2);
  out.clock_s = envelope_times(options);
  out.identifiability = identifiability(out.records, options.prior);
  // Runs grouped by their test-run layout: every unit of a file shares one
  // as a rule, but a logger that drops records gives each run its own. What
  // depends on the layout alone (the conditioning, rows² per covariance, and
  // the schemes' navigation models) is built once per layout, the layouts in
  // parallel, and dropped when its units are done. Each layout's work is
  // sequential, so the bits do not depend on the threads.
  const std::vector<UnitTestRun>& runs = out.records.runs;
  std::vector<std::vector<std::size_t>> by_layout;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::size_t L = 0;
    while (L < by_layout.size() && !(runs[by_layout[L].front()].layout == runs[i].layout)) ++L;
    if (L == by_layout.size()) by_layout.emplace_back();
    by_layout[L].push_back(i);
  }
  out.units.resize(runs.size());
  tbb::parallel_for(std::size_t{0}, by_layout.size(), [&](std::size_t L) {
    const UnitConditioning shared = unit_conditioning(out.records, runs[by_layout[L].front()].layout, options.prior);
    std::vector<SchemeModel> scheme_models;
    for (const std::size_t i : by_layout[L]) {
      const UnitPosterior posterior = condition_unit(out.records, runs[i], shared);
      if (scheme_models.empty())
        for (Scheme s : options.schemes)
          scheme_models.push_back(
              scheme_model(out.records, posterior, s, options.prior, out.clock_s, options.realignment_duration_s));
      UnitResult& u = out.units[i];
      u.run = runs[i].id;
      u.estimates = estimate_unit(out.records, posterior, options.prior);
      u.consistency_chi2 = posterior.consistency_chi2;
      u.consistency_dof = posterior.consistency_dof;
      u.consistency_p = posterior.consistency_p;
      u.consistency_band = posterior.consistency_band;
      for (const SchemeModel& m : scheme_models) u.schemes.push_back(predict_scheme(out.records, runs[i], posterior, m));
      choose_scheme(u, options);
    }
  });
  return out;
}

}  // namespace insmc::compensate
