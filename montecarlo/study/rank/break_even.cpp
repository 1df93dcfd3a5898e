#include "montecarlo/study/rank/break_even.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

#include "lib/common/assert.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/uncertainty/random_fraction.h"
#include "montecarlo/study/model/study_map.h"

namespace insmc::mc {
namespace {

bool is_bound(Assumption a) { return bound_slot(a) >= 0; }

/// Real roots in [lo, hi] of c0 + c1 v + c2 v² (c2 may be 0).
std::vector<double> roots_in(double c0, double c1, double c2, double lo, double hi) {
  std::vector<double> r;
  // A quadratic term below round-off of the others is none (the mean squares
  // are differences of sums of squares).
  if (c2 == 0 || std::abs(c2) <= 1e-12 * (std::abs(c0) + std::abs(c1))) {
    if (c1 != 0) r.push_back(-c0 / c1);
  } else {
    const double disc = c1 * c1 - 4 * c2 * c0;
    if (disc >= 0) {
      // The form that does not cancel: q = −(c1 + sign(c1)√disc)/2, roots q/c2 and c0/q.
      const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
      r.push_back(q / c2);
      if (q != 0) r.push_back(c0 / q);
    }
  }
  std::erase_if(r, [&](double v) { return !(v >= lo && v <= hi); });
  std::sort(r.begin(), r.end());
  return r;
}

}  // namespace

std::size_t leader_of(const std::vector<double>& rms) {
  return static_cast<std::size_t>(std::min_element(rms.begin(), rms.end()) - rms.begin());
}

int bound_slot(Assumption a) {
  switch (a) {
    case Assumption::kAlignDriftError: return uncertainty_slot::kAlignDriftError;
    case Assumption::kResetVelocityError: return uncertainty_slot::kResetVelocityError;
    case Assumption::kResetPositionError: return uncertainty_slot::kResetPositionError;
    case Assumption::kRealignAzimuthError: return uncertainty_slot::kRealignAzimuthError;
    default: return -1;
  }
}

namespace {

int bound_slot_count(Assumption a) {
  return a == Assumption::kRealignAzimuthError ? 1 : is_bound(a) ? 3 : 0;
}

}  // namespace

bool applies_to(Assumption a, System system) {
  if (!is_bound(a)) return true;
  return catalogue()[static_cast<std::size_t>(bound_slot(a))].applies == Applies::kBoth || system == System::kTheodolite;
}

std::string_view to_string(Assumption a) {
  switch (a) {
    case Assumption::kAlignDriftError: return "alignment_drift_error";
    case Assumption::kResetVelocityError: return "reset_velocity_error";
    case Assumption::kResetPositionError: return "reset_position_error";
    case Assumption::kRealignAzimuthError: return "realignment_azimuth_error";
    case Assumption::kRandomFraction: return "random_fraction";
    case Assumption::kTestDuration: return "test_duration";
  }
  return "?";
}

std::string_view si_unit(Assumption a) {
  switch (a) {
    case Assumption::kAlignDriftError: return "radps";
    case Assumption::kResetVelocityError: return "mps";
    case Assumption::kResetPositionError: return "m";
    case Assumption::kRealignAzimuthError: return "rad";
    case Assumption::kRandomFraction: return "1";
    case Assumption::kTestDuration: return "s";
  }
  return "?";
}

StudyConfig with_assumption(const StudyConfig& config, Assumption a, double value) {
  StudyConfig c = config;
  if (is_bound(a)) {
    for (int k = 0; k < bound_slot_count(a); ++k) {
      ParameterDistribution& p = c.uncertainties.at(bound_slot(a) + k);
      p.kind = DistributionKind::kUniform;
      p.bound_si = value;
    }
  } else if (a == Assumption::kRandomFraction) {
    apply_random_fraction(c.uncertainties, value);
  } else {
    c.test.duration_s = value;
  }
  return c;
}

double study_value(const StudyConfig& config, Assumption a) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const UncertaintyModel& u = config.uncertainties;
  if (is_bound(a)) {
    const ParameterDistribution& p = u.at(bound_slot(a));
    for (int k = 0; k < bound_slot_count(a); ++k) {
      const ParameterDistribution& q = u.at(bound_slot(a) + k);
      if (q.kind != p.kind || q.bound_si != p.bound_si) return nan;
    }
    return p.kind == DistributionKind::kZero ? 0.0 : p.kind == DistributionKind::kUniform ? p.bound_si : nan;
  }
  if (a == Assumption::kTestDuration) return config.test.duration_s;
  // F from the bounds, when they are a split of Table 3.1's totals.
  const double c = u.at(uncertainty_slot::kMisalignConst).bound_si, r = u.at(uncertainty_slot::kMisalignAlign).bound_si;
  if (c + r <= 0) return nan;
  UncertaintyModel split = u;
  apply_random_fraction(split, r / (c + r));
  for (int i = 0; i < uncertainty_slot::kDim; ++i)
    if (std::abs(split.at(i).bound_si - u.at(i).bound_si) > 1e-12 * std::max(1e-300, u.at(i).bound_si)) return nan;
  return r / (c + r);
}

RmsTable predicted_horizontal_rms(const StudyConfig& config) {
  StudyConfig c = config;
  c.with_grid = false;
  const StudyLayout layout = make_layout(c);
  const StudyMap map(c, layout);
  RmsTable out(static_cast<std::size_t>(layout.n_systems));
  for (int j = 0; j < layout.n_systems; ++j)
    for (int k = 0; k < layout.n_times; ++k) {
      if (!layout.is_report_time[static_cast<std::size_t>(k)]) continue;
      std::vector<double> per_scheme;
      for (std::size_t i = 0; i < c.schemes.size(); ++i)
        per_scheme.push_back(
            map.predicted_rms()[static_cast<std::size_t>(layout.index(static_cast<int>(i), j, k, Axis::kHorizontal))]);
      out[static_cast<std::size_t>(j)].push_back(std::move(per_scheme));
    }
  return out;
}

namespace {

/// Counts the study maps built, for the caller's progress.
class MapCounter {
 public:
  MapCounter(const BreakEvenProgress& report, std::uint64_t total, std::string_view stage)
      : report_(report), total_(total), stage_(stage) {}
  void built() {
    const std::uint64_t done = ++done_;
    if (report_) report_(stage_, done, total_);
  }

 private:
  const BreakEvenProgress& report_;
  std::uint64_t total_;
  std::string_view stage_;
  std::atomic<std::uint64_t> done_{0};
};

/// Each value's study built and predicted on its own: side by side.
std::vector<RmsTable> rms_along(const StudyConfig& config, Assumption a, const std::vector<double>& values,
                                MapCounter& counter) {
  std::vector<RmsTable> out(values.size());
  tbb::parallel_for(std::size_t{0}, values.size(), [&](std::size_t q) {
    out[q] = predicted_horizontal_rms(with_assumption(config, a, values[q]));
    counter.built();
  });
  return out;
}

/// The study maps of an assumption's polynomials (below): two for a bound, three for F.
std::size_t polynomial_points(Assumption a) { return is_bound(a) ? 2 : 3; }

/// Every output's mean square as a polynomial c0 + c1 v + c2 v² in the
/// assumption's variable v (b² for a bound, F for the random fraction),
/// from exact evaluations.
struct MeanSquarePolynomials {
  std::vector<std::vector<std::vector<std::array<double, 3>>>> c;  // [j][k][i]
  double at(std::size_t j, std::size_t k, std::size_t i, double v) const {
    const auto& p = c[j][k][i];
    return p[0] + p[1] * v + p[2] * v * v;
  }
};

MeanSquarePolynomials mean_square_polynomials(const StudyConfig& config, Assumption a, MapCounter& counter) {
  const bool bound = is_bound(a);
  const double b1 = bound ? catalogue()[static_cast<std::size_t>(bound_slot(a))].default_bound_si : 0.0;
  const std::vector<double> points = bound ? std::vector<double>{0.0, b1} : std::vector<double>{0.0, 0.5, 1.0};
  INSMC_ASSERT(points.size() == polynomial_points(a), "{} points", points.size());
  const std::vector<RmsTable> at = rms_along(config, a, points, counter);
  MeanSquarePolynomials p;
  p.c.resize(at[0].size());
  for (std::size_t j = 0; j < at[0].size(); ++j)
    for (std::size_t k = 0; k < at[0][j].size(); ++k) {
      p.c[j].emplace_back();
      for (std::size_t i = 0; i < at[0][j][k].size(); ++i) {
        auto ms = [&](std::size_t q) { return at[q][j][k][i] * at[q][j][k][i]; };
        if (bound) {
          p.c[j][k].push_back({ms(0), (ms(1) - ms(0)) / (b1 * b1), 0.0});
        } else {  // through F = 0, ½, 1
          p.c[j][k].push_back({ms(0), 4 * ms(1) - 3 * ms(0) - ms(2), 2 * (ms(0) + ms(2) - 2 * ms(1))});
        }
      }
    }
  return p;
}

}  // namespace

BreakEven break_even(const StudyConfig& config, double max_test_duration_s, const BreakEvenProgress& progress) {
  // The test duration's scan: whole filter intervals, over whole minutes
  // (or intervals, when an interval is longer); bisection follows below.
  const double tau = config.test.filter_interval_s;
  const auto whole = [&](double t) { return tau * std::ceil(t / tau - 1e-9); };
  const double lo = whole(std::max(4 * tau, 60.0)), step = whole(std::max(tau, 60.0));
  const double hi = std::min(max_test_duration_s, kMaxStudyIntervals * tau);  // the study's own limit
  std::vector<double> scan;
  for (double t = lo; t <= hi + 1e-9 && scan.size() < 1000; t += step) scan.push_back(t);
  std::uint64_t maps = scan.size();
  for (const Assumption a : kAllAssumptions)
    if (a != Assumption::kTestDuration) maps += polynomial_points(a);
  MapCounter counter(progress, maps, "break-even searches");

  BreakEven out;
  out.at_study = predicted_horizontal_rms(config);
  const RmsTable& base = out.at_study;
  const std::size_t n_schemes = config.schemes.size();
  auto add = [&](std::size_t j, std::size_t k, Assumption a, std::size_t leader, std::size_t c, double v) {
    out.crossings.push_back({config.systems[j], config.report_times_s[k], a, config.schemes[leader], config.schemes[c], v});
  };
  // Every assumption's polynomials side by side (a study map each), then
  // the crossings and curves in the assumptions' order.
  std::vector<MeanSquarePolynomials> polynomials(std::size(kAllAssumptions));
  tbb::parallel_for(std::size_t{0}, polynomials.size(), [&](std::size_t q) {
    if (kAllAssumptions[q] != Assumption::kTestDuration)
      polynomials[q] = mean_square_polynomials(config, kAllAssumptions[q], counter);
  });
  for (std::size_t q = 0; q < polynomials.size(); ++q) {
    const Assumption a = kAllAssumptions[q];
    if (a == Assumption::kTestDuration) continue;
    const bool bound = is_bound(a);
    const MeanSquarePolynomials& p = polynomials[q];
    // A bound is searched within the catalogue's physical range of it (--bound's).
    const double ceiling = bound ? bound_range(catalogue()[static_cast<std::size_t>(bound_slot(a))]).max_si : 1.0;
    // The plot's range: 10 defaults, or 3 times the first change at the last report time.
    double largest = bound ? std::min(ceiling, catalogue()[static_cast<std::size_t>(bound_slot(a))].default_bound_si * 10) : 1.0;
    double first_change = 0.0;
    for (std::size_t j = 0; j < base.size(); ++j)
      for (std::size_t k = 0; k < base[j].size(); ++k) {
        const std::size_t leader = leader_of(base[j][k]);
        for (std::size_t c = 0; c < n_schemes; ++c) {
          if (c == leader) continue;
          const auto& l = p.c[j][k][leader];
          const auto& o = p.c[j][k][c];
          // The leader's mean square less the challenger's: zero at a tie.
          for (double v : roots_in(l[0] - o[0], l[1] - o[1], l[2] - o[2], 0.0, bound ? ceiling * ceiling : 1.0)) {
            const double value = bound ? std::sqrt(v) : v;
            add(j, k, a, leader, c, value);
            if (k + 1 == base[j].size() && (first_change == 0.0 || value < first_change)) first_change = value;
          }
        }
      }
    if (bound) largest = std::min(ceiling, std::max(largest, 3 * first_change));
    // The curves: 41 values over [0, largest] (bounds) or [0, 1] (F).
    AssumptionCurve curve{a, {}, {}};
    for (int q = 0; q <= 40; ++q) {
      const double value = largest * q / 40.0, v = bound ? value * value : value;
      RmsTable t(base.size());
      for (std::size_t j = 0; j < base.size(); ++j)
        for (std::size_t k = 0; k < base[j].size(); ++k) {
          t[j].emplace_back();
          for (std::size_t i = 0; i < n_schemes; ++i) t[j][k].push_back(std::sqrt(std::max(0.0, p.at(j, k, i, v))));
        }
      curve.values_si.push_back(value);
      curve.rms.push_back(std::move(t));
    }
    out.curves.push_back(std::move(curve));
  }
  // The test duration: the scan above, then bisection between its points.
  const std::vector<RmsTable> along = rms_along(config, Assumption::kTestDuration, scan, counter);
  const auto sign_changes = [&](std::size_t s) {
    for (std::size_t j = 0; j < base.size(); ++j)
      for (std::size_t k = 0; k < base[j].size(); ++k) {
        const std::size_t leader = leader_of(base[j][k]);
        for (std::size_t c = 0; c < n_schemes; ++c)
          if (c != leader && (along[s][j][k][leader] < along[s][j][k][c]) !=
                                 (along[s + 1][j][k][leader] < along[s + 1][j][k][c]))
            return true;
      }
    return false;
  };
  // The bisections' study maps: every whole interval inside a scan step
  // where a first place changes hands, built side by side once (the
  // crossings of all systems, times and challengers share them; a step of
  // more than 8 intervals is bisected with maps built as needed).
  std::vector<double> inner;
  for (std::size_t s = 0; s + 1 < scan.size(); ++s) {
    if (!sign_changes(s)) continue;
    std::vector<double> step_points;
    for (double m = whole(scan[s] + tau); m < scan[s + 1] - 1e-9 && step_points.size() <= 8; m = whole(m + tau))
      step_points.push_back(m);
    if (step_points.size() <= 8) inner.insert(inner.end(), step_points.begin(), step_points.end());
  }
  MapCounter bisection_counter(progress, inner.size(), "test-duration bisection");
  const std::vector<RmsTable> at_inner = rms_along(config, Assumption::kTestDuration, inner, bisection_counter);
  const auto rms_at = [&](double m) {
    const auto it = std::find(inner.begin(), inner.end(), m);
    return it != inner.end() ? at_inner[static_cast<std::size_t>(it - inner.begin())]
                             : predicted_horizontal_rms(with_assumption(config, Assumption::kTestDuration, m));
  };
  for (std::size_t j = 0; j < base.size(); ++j)
    for (std::size_t k = 0; k < base[j].size(); ++k) {
      const std::size_t leader = leader_of(base[j][k]);
      for (std::size_t c = 0; c < n_schemes; ++c) {
        if (c == leader) continue;
        const auto sign_at = [&](const RmsTable& t) { return t[j][k][leader] < t[j][k][c]; };
        for (std::size_t s = 0; s + 1 < scan.size(); ++s) {
          if (sign_at(along[s]) == sign_at(along[s + 1])) continue;
          // Bisection on whole intervals: b ends as the first T of the other sign.
          const bool first = sign_at(along[s]);
          double a = scan[s], b = scan[s + 1];
          for (int it = 0; it < 60 && b - a > tau + 1e-9; ++it) {
            const double m = whole(a + std::floor((b - a) / tau / 2) * tau);
            if (m <= a || m >= b) break;
            if (sign_at(rms_at(m)) == first)
              a = m;
            else
              b = m;
          }
          add(j, k, Assumption::kTestDuration, leader, c, b);
        }
      }
    }
  out.curves.push_back({Assumption::kTestDuration, scan, along});
  std::stable_sort(out.crossings.begin(), out.crossings.end(), [](const Crossing& x, const Crossing& y) {
    if (x.system != y.system) return x.system < y.system;
    if (x.t_s != y.t_s) return x.t_s < y.t_s;
    if (x.assumption != y.assumption) return x.assumption < y.assumption;
    return x.value_si < y.value_si;
  });
  return out;
}

}  // namespace insmc::mc
