#include "montecarlo/records/gap/fit/likelihood_fit.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <tuple>

#include "lib/common/assert.h"

namespace insmc::gap {

bool LikelihoodFit::at_limit() const {
  return std::any_of(parameters.begin(), parameters.end(),
                     [](const ParameterFit& p) { return p.at_lower || p.at_upper; });
}

namespace {

/// A log-likelihood along one parameter's lattice (the others held).
using Line = std::function<double(int)>;

/// Golden section on the lattice: b is the best so far, a ≤ b ≤ c, and
/// f(a), f(c) ≤ f(b) are known. Probes the wider side until b's neighbours
/// on the lattice are both bracketed.
int refine(const Line& f, int a, int b, int c) {
  constexpr double kGolden = 0.381966;  // (3 − √5)/2
  double fb = f(b);
  while (b - a > 1 || c - b > 1) {
    const bool right = c - b >= b - a;
    const int x = right ? b + std::max(1, static_cast<int>(std::lround(kGolden * (c - b))))
                        : b - std::max(1, static_cast<int>(std::lround(kGolden * (b - a))));
    const double fx = f(x);
    if (fx > fb) {
      (right ? a : c) = b;
      b = x, fb = fx;
    } else {
      (right ? c : a) = x;
    }
  }
  return b;
}

/// The whole range at `coarse` lattice steps (×10) plus `start`, then refined
/// between the best point's coarse neighbours.
int coarse_search(const Line& f, int last, int coarse, int start) {
  std::vector<int> points;
  for (int k = 0; k < last; k += coarse) points.push_back(k);
  points.push_back(last);
  points.push_back(start);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::size_t best = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (f(points[i]) > f(points[best])) best = i;
  const int a = points[best == 0 ? 0 : best - 1], c = points[std::min(best + 1, points.size() - 1)];
  return refine(f, a, points[best], c);
}

/// From `start`, steps of `step` lattice points that double while the
/// log-likelihood rises, then refined: the search after the first round of
/// coordinate ascent and inside the profile, where the maximum is near.
int local_search(const Line& f, int last, int start, int step) {
  int a = std::max(0, start - step), b = start, c = std::min(last, start + step);
  for (const int dir : {+1, -1}) {
    int& ahead = dir > 0 ? c : a;
    int& behind = dir > 0 ? a : c;
    if (ahead == b || !(f(ahead) > f(b))) continue;
    while (true) {  // climb: b moves to `ahead` while that is better
      behind = b, b = ahead;
      const int limit = dir > 0 ? last : 0;
      if (b == limit) break;
      step *= 2;
      ahead = dir > 0 ? std::min(last, b + step) : std::max(0, b - step);
      if (!(f(ahead) > f(b))) break;
    }
    break;  // a rise one way means the maximum is not the other way
  }
  return refine(f, a, b, c);
}

struct Ascent {
  std::vector<int> index;
  double value = 0.0;
  int rounds = 0;
};

/// Coordinate ascent from `index` on the sum over `runs`, parameter `fixed`
/// (if any) held. `coarse`: the first round searches each parameter's whole
/// range; else every search is local (a warm start), from steps of
/// `local_step` lattice points (0: ×1.2, as later rounds move little).
Ascent ascend(LikelihoodLattice& L, std::span<const int> runs, std::vector<int> index, std::optional<int> fixed,
              bool coarse, int local_step) {
  const int dims = L.dimensions();
  const int free = dims - (fixed ? 1 : 0);
  Ascent out;
  for (int round = 1; round <= kMaxAscentRounds && free > 0; ++round) {
    out.rounds = round;
    bool changed = false;
    for (int p = 0; p < dims; ++p) {
      if (fixed && *fixed == p) continue;
      const Line f = [&](int k) {
        std::vector<int> at = index;
        at[static_cast<std::size_t>(p)] = k;
        return L.sum(at, runs);
      };
      const int k0 = index[static_cast<std::size_t>(p)];
      const int k =
          round == 1 && coarse
              ? coarse_search(f, L.last(p), L.per_decade(p), k0)
              : local_search(f, L.last(p), k0, local_step > 0 ? local_step : std::max(1, L.per_decade(p) / 12));
      changed = changed || k != k0;
      index[static_cast<std::size_t>(p)] = k;
    }
    // One free parameter: its 1-D search is already the maximum.
    if (!changed || free == 1) break;
  }
  out.value = L.sum(index, runs);
  out.index = std::move(index);
  return out;
}

/// The profile log-likelihood of parameter p: the maximum over the others
/// with p held at each lattice point, warm-started on the ridge extrapolated
/// from the two nearest points already profiled (linear in log space for a
/// quadratic maximum), so that the local search mostly just confirms it.
class Profile {
 public:
  Profile(LikelihoodLattice& L, std::span<const int> runs, const Ascent& best, int p) : L_(L), runs_(runs), p_(p) {
    points_.emplace(best.index[static_cast<std::size_t>(p)], best);
  }
  double operator()(int k) {
    if (auto it = points_.find(k); it != points_.end()) return it->second.value;
    // The two profiled points nearest k (the maximum is always one).
    std::vector<const std::pair<const int, Ascent>*> near;
    for (const auto& point : points_) near.push_back(&point);
    std::sort(near.begin(), near.end(),
              [k](auto* a, auto* b) { return std::abs(a->first - k) < std::abs(b->first - k); });
    std::vector<int> start = near[0]->second.index;
    if (near.size() > 1) {
      const double t = static_cast<double>(k - near[0]->first) / (near[0]->first - near[1]->first);
      for (int q = 0; q < L_.dimensions(); ++q) {
        const auto u = static_cast<std::size_t>(q);
        const int moved = near[0]->second.index[u] +
                          static_cast<int>(std::lround(t * (near[0]->second.index[u] - near[1]->second.index[u])));
        start[u] = std::clamp(moved, 0, L_.last(q));
      }
    }
    start[static_cast<std::size_t>(p_)] = k;
    const Ascent a = ascend(L_, runs_, std::move(start), p_, false, 1);
    return points_.emplace(k, a).first->second.value;
  }

 private:
  LikelihoodLattice& L_;
  std::span<const int> runs_;
  int p_;
  std::map<int, Ascent> points_;
};

/// One end of the interval where the profile stays ≥ max − drop. Near a
/// maximum the profile is quadratic, so g(k) = √(max − profile(k)) is linear
/// in k: the crossing g = √drop is extrapolated from the first step out, then
/// found by secant steps in g between the last point inside and the first
/// outside (every third step a bisection, so a profile far from quadratic
/// still converges), down to adjacent lattice points; the crossing is
/// interpolated in log value between them. Returns the value and whether
/// the end is open (the profile stays within the drop up to the limit).
std::pair<double, bool> interval_end(LikelihoodLattice& L, Profile& profile, int p, int k_best, double max_value,
                                     double drop, int dir) {
  const int limit = dir > 0 ? L.last(p) : 0;
  if (k_best == limit) return {L.value(p, limit), true};
  const double target = std::sqrt(drop);
  const auto g = [&](int k) { return std::sqrt(std::max(0.0, max_value - profile(k))); };
  const auto clamp = [&](int k) { return dir > 0 ? std::min(k, limit) : std::max(k, limit); };
  int inside = k_best, outside = -1;
  int k = clamp(k_best + dir);
  for (int step = 0;; ++step) {
    if (g(k) <= target) {
      inside = k;
      if (k == limit) return {L.value(p, limit), true};
    } else {
      outside = k;
    }
    const int distance = std::abs(inside - k_best);
    if (outside < 0) {
      // Not yet outside: extrapolate g through the maximum (g = 0) and the
      // farthest point inside, at least one step on and at most ×4.
      const double slope = g(inside) / distance;
      const double reach = slope > 0.0 ? std::ceil(target / slope) : 2.0 * distance;
      k = clamp(k_best + dir * static_cast<int>(std::clamp(reach, distance + 1.0, 4.0 * distance)));
      continue;
    }
    const int width = std::abs(outside - inside);
    if (width <= 1) break;
    int offset = width / 2;
    if (step % 3 != 2) {
      const double g_in = g(inside), g_out = g(outside);
      const double t = std::isfinite(g_out) ? (target - g_in) / (g_out - g_in) : 0.0;
      offset = std::clamp(static_cast<int>(std::lround(t * width)), 1, width - 1);
    }
    k = inside + dir * offset;
  }
  const double f_in = profile(inside), f_out = profile(outside), threshold = max_value - drop;
  const double t = std::isfinite(f_out) ? (f_in - threshold) / (f_in - f_out) : 0.0;
  const double log_in = std::log(L.value(p, inside)), log_out = std::log(L.value(p, outside));
  return {std::exp(log_in + t * (log_out - log_in)), false};
}

ProfileInterval profile_interval(LikelihoodLattice& L, Profile& profile, int p, int k_best, double max_value,
                                 double drop) {
  ProfileInterval ci;
  std::tie(ci.lower_si, ci.open_lower) = interval_end(L, profile, p, k_best, max_value, drop, -1);
  std::tie(ci.upper_si, ci.open_upper) = interval_end(L, profile, p, k_best, max_value, drop, +1);
  return ci;
}

}  // namespace

LikelihoodFit fit_likelihood(LikelihoodLattice& L, std::span<const int> runs, bool intervals, Search search,
                             std::span<const int> from) {
  const int before = L.evaluations();
  std::vector<int> start(from.begin(), from.end());
  if (start.empty()) {
    start.resize(static_cast<std::size_t>(L.dimensions()));
    for (int p = 0; p < L.dimensions(); ++p) start[static_cast<std::size_t>(p)] = L.nearest(p, L.parameter(p).start_si);
  }
  INSMC_ASSERT(static_cast<int>(start.size()) == L.dimensions(), "start of {} parameters, expected {}", start.size(),
               L.dimensions());
  const Ascent best = ascend(L, runs, start, std::nullopt, search == Search::kCoarse, 0);

  LikelihoodFit fit;
  fit.index = best.index;
  fit.log_likelihood = best.value;
  fit.rounds = best.rounds;
  for (int p = 0; p < L.dimensions(); ++p) {
    const int k = best.index[static_cast<std::size_t>(p)];
    ParameterFit q;
    q.name = L.parameter(p).name;
    q.value_si = L.value(p, k);
    q.at_lower = k == 0;
    q.at_upper = k == L.last(p);
    if (intervals) {
      Profile profile(L, runs, best, p);
      q.ci95 = profile_interval(L, profile, p, k, best.value, kDrop95);
      q.ci68 = profile_interval(L, profile, p, k, best.value, kDrop68);
    }
    fit.parameters.push_back(std::move(q));
  }
  fit.evaluations = L.evaluations() - before;
  return fit;
}

CrossValidation cross_validate(LikelihoodLattice& L, std::span<const double> null_per_run) {
  return cross_validate({&L, &L}, null_per_run);
}

CrossValidation cross_validate(std::array<LikelihoodLattice*, 2> folds, std::span<const double> null_per_run,
                               Search search, std::span<const int> start) {
  for (const LikelihoodLattice* L : folds)
    INSMC_ASSERT(static_cast<int>(null_per_run.size()) == L->runs(), "null log-likelihoods of {} runs, expected {}",
                 null_per_run.size(), L->runs());
  const bool shared = folds[0] == folds[1];
  const int before = folds[0]->evaluations() + (shared ? 0 : folds[1]->evaluations());
  std::array<std::vector<int>, 2> half;
  for (int r = 0; r < folds[0]->runs(); ++r) half[static_cast<std::size_t>(r % 2)].push_back(r);
  CrossValidation cv;
  for (std::size_t f = 0; f < 2; ++f) {
    LikelihoodLattice& L = *folds[f];
    const std::vector<int>& train = half[f];
    const std::vector<int>& held_out = half[1 - f];
    const LikelihoodFit fit = fit_likelihood(L, train, false, search, start);
    double null_sum = 0.0;
    for (int r : held_out) null_sum += null_per_run[static_cast<std::size_t>(r)];
    cv.fold_gain[f] = L.sum(fit.index, held_out) - null_sum;
    for (const ParameterFit& q : fit.parameters) cv.fold_values[f].push_back(q.value_si);
    cv.gain += cv.fold_gain[f];
  }
  cv.evaluations = folds[0]->evaluations() + (shared ? 0 : folds[1]->evaluations()) - before;
  return cv;
}

}  // namespace insmc::gap
