#include "montecarlo/records/gap/fit/candidate_fit.h"

#include "montecarlo/records/gap/candidates/layout_extensions.h"
#include "lib/common/assert.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <utility>

namespace insmc::gap {

namespace {

std::vector<const runs::Extension*> pointers(const std::vector<runs::Extension>& selected, const runs::Extension* added) {
  std::vector<const runs::Extension*> e;
  for (const runs::Extension& s : selected) e.push_back(&s);
  if (added) e.push_back(added);
  return e;
}

/// Which layouts some run of any part is analysed under.
std::vector<bool> layouts_used_by(std::span<const runs::PreparedRuns* const> parts) {
  std::vector<bool> used = used_layouts(*parts.front());
  for (const runs::PreparedRuns* p : parts.subspan(1)) {
    const std::vector<bool> more = used_layouts(*p);
    for (std::size_t L = 0; L < used.size(); ++L) used[L] = used[L] || more[L];
  }
  return used;
}

/// Evaluates grid points `ks` of `c` on every run of every part (out[i] the
/// sums of parts[i]), as many points at a time as there are threads: their
/// extensions built one after another (a candidate's build fills the
/// layout's response cache, which is not shared across threads), then the
/// run models and the runs under them (most of the cost) side by side, each
/// layout's model once for all parts. A random process' extension holds
/// rows × knots, so only the points being evaluated hold theirs. Each
/// point's result is its own, so neither the order, the thread count nor
/// the other parts change it. Without `keep_keyed` only the run sets and
/// sums stay; with it (points evaluated before) the run sets are kept.
void evaluate_points(std::span<CandidateSums* const> out, std::span<const runs::PreparedRuns* const> parts,
                     const Candidate& c, const std::vector<std::vector<runs::Extension>>& selected,
                     LayoutExtensions& build, const std::vector<bool>& used, std::span<const int> ks, bool keep_keyed) {
  const runs::PreparedRuns& first_part = *parts.front();
  const auto chunk = static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
  for (std::size_t first = 0; first < ks.size(); first += chunk) {
    const std::span<const int> batch = ks.subspan(first, std::min(chunk, ks.size() - first));
    std::vector<std::vector<std::optional<runs::Extension>>> extensions(batch.size());
    for (std::size_t b = 0; b < batch.size(); ++b) extensions[b] = build.build(c, c.grid_point(batch[b]), used);
    tbb::parallel_for(std::size_t{0}, batch.size(), [&](std::size_t b) {
      std::vector<std::vector<const runs::Extension*>> on_lattice(first_part.lattices.size());
      for (std::size_t l = 0; l < first_part.lattices.size(); ++l)
        if (extensions[b][l]) on_lattice[l] = pointers(selected[l], &*extensions[b][l]);
      const auto k = static_cast<std::size_t>(batch[b]);
      std::vector<EvaluatedRuns> e = evaluate_runs(parts, on_lattice, used);
      for (std::size_t i = 0; i < parts.size(); ++i) {
        if (!keep_keyed) {
          out[i]->sets[k] = e[i].set(parts[i]->keys);
          e[i].keyed.resize(0, 0);
        }
        out[i]->at[k] = std::move(e[i]);
      }
    });
    for (CandidateSums* o : out)
      for (int k : batch) o->keyed_kept[static_cast<std::size_t>(k)] = keep_keyed;  // bits: not from the threads
  }
}

/// Each part searched on its grid as evaluate_candidate says, every point
/// any part's search asks for evaluated once on all parts; a part sees as
/// evaluated the points its own search asked for.
std::vector<CandidateSums> evaluate_on_grid(std::span<const runs::PreparedRuns* const> parts, const Candidate& c,
                                            const std::vector<std::vector<runs::Extension>>& selected,
                                            std::shared_ptr<LayoutExtensions> build, const NullCalibration& m0,
                                            std::vector<std::vector<std::vector<int>>> groups) {
  const std::vector<bool> used = layouts_used_by(parts);
  const int K = c.grid_size();
  std::vector<CandidateSums> out(parts.size());
  std::vector<CandidateSums*> all;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    CandidateSums& o = out[i];
    const runs::PreparedRuns* p = parts[i];
    o.keys = &p->keys;
    o.at.resize(static_cast<std::size_t>(K));
    o.sets.resize(static_cast<std::size_t>(K));
    o.evaluated.assign(static_cast<std::size_t>(K), false);
    o.keyed_kept.assign(static_cast<std::size_t>(K), false);
    // Its own layouts only: a null run may sit on a layout of its own.
    o.reevaluate = [p, &c, &selected, build, own_used = used_layouts(*p)](CandidateSums& s, std::span<const int> ks) {
      CandidateSums* one[] = {&s};
      const runs::PreparedRuns* own[] = {p};
      evaluate_points(one, own, c, selected, *build, own_used, ks, true);
    };
    all.push_back(&o);
    if (groups[i].empty()) {
      groups[i].emplace_back(p->runs.size());
      for (std::size_t r = 0; r < p->runs.size(); ++r) groups[i].front()[r] = static_cast<int>(r);
    }
  }
  std::vector<bool> computed(static_cast<std::size_t>(K), false);
  // Points asked for by part i (asked[i]); each computed once on every part.
  const auto evaluate = [&](const std::vector<std::vector<int>>& asked) {
    std::vector<int> ks;
    for (const std::vector<int>& a : asked)
      for (int k : a)
        if (!computed[static_cast<std::size_t>(k)]) ks.push_back(k);
    std::sort(ks.begin(), ks.end());
    ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
    evaluate_points(all, parts, c, selected, *build, used, ks, false);
    for (int k : ks) computed[static_cast<std::size_t>(k)] = true;
    for (std::size_t i = 0; i < parts.size(); ++i)
      for (int k : asked[i]) out[i].evaluated[static_cast<std::size_t>(k)] = true;
  };
  // Grid index = first-parameter index × rest + rest index (grid_point).
  const int first = static_cast<int>(c.parameters.front().grid.size()), rest = K / first;
  for (int j = 0; j < rest; ++j) {
    std::vector<int> every_other;
    for (int i = 0; i < first; i += 2) every_other.push_back(i * rest + j);
    evaluate(std::vector<std::vector<int>>(parts.size(), every_other));
    std::vector<std::vector<int>> next_to_best(parts.size());
    for (std::size_t part = 0; part < parts.size(); ++part)
      for (const std::vector<int>& runs : groups[part]) {
        int best = -1;
        double best_gap = std::numeric_limits<double>::infinity();
        for (int i = 0; i < first; i += 2) {
          const double g = gap_value(out[part].sets[static_cast<std::size_t>(i * rest + j)], runs, m0);
          if (g < best_gap) best_gap = g, best = i;
        }
        for (int i : {best - 1, best + 1})
          if (i >= 0 && i < first) next_to_best[part].push_back(i * rest + j);
      }
    evaluate(next_to_best);
  }
  return out;
}

/// Amplitude candidates: the fit without the candidate and the signatures
/// per layout, made once and given to every part with its runs' values.
std::vector<CandidateSums> evaluate_amplitudes(std::span<const runs::PreparedRuns* const> parts, const Candidate& c,
                                               const std::vector<std::vector<runs::Extension>>& selected,
                                               LayoutExtensions& build) {
  const runs::PreparedRuns& p = *parts.front();
  CandidateSums shared;
  const std::vector<bool> used = layouts_used_by(parts);
  shared.amplitudes = true;
  std::vector<std::vector<const runs::Extension*>> on_lattice(p.lattices.size());
  for (std::size_t l = 0; l < p.lattices.size(); ++l) on_lattice[l] = pointers(selected[l], nullptr);
  shared.fit = runs::layout_analysers(p, on_lattice, used);
  const std::vector<int> amp = c.amplitude_indices();
  shared.amplitude_limit.resize(static_cast<Eigen::Index>(amp.size()));
  for (std::size_t j = 0; j < amp.size(); ++j)
    shared.amplitude_limit[static_cast<Eigen::Index>(j)] = c.parameters[static_cast<std::size_t>(amp[j])].grid.front();
  shared.signature.resize(static_cast<std::size_t>(c.grid_size()));
  for (int k = 0; k < c.grid_size(); ++k) {
    std::vector<Eigen::MatrixXd>& signature = shared.signature[static_cast<std::size_t>(k)];
    signature.resize(p.layouts.size());
    for (std::size_t j = 0; j < amp.size(); ++j) {
      // The signature of amplitude j alone, at unit size (SI).
      std::vector<double> theta = c.grid_point(k);
      theta[static_cast<std::size_t>(amp[j])] = 1.0;
      const std::vector<std::optional<runs::Extension>> e = build.build(c, theta, used);
      for (std::size_t L = 0; L < p.layouts.size(); ++L) {
        if (!used[L]) continue;
        const runs::Extension& on_lattice_e = *e[static_cast<std::size_t>(p.lattice_of[L])];
        const Eigen::VectorXd z = shared.fit[L]->normalized_linear(runs::select_rows(on_lattice_e, p.lattice_rows[L]).mean);
        Eigen::MatrixXd& Z = signature[L];
        if (Z.size() == 0) Z.resize(z.size(), static_cast<Eigen::Index>(amp.size()));
        Z.col(static_cast<Eigen::Index>(j)) = z;
      }
    }
  }
  std::vector<CandidateSums> out(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    CandidateSums& o = out[i];
    const runs::PreparedRuns& part = *parts[i];
    if (i + 1 < parts.size()) o = shared;
    else o = std::move(shared);
    o.keys = &part.keys;
    o.layout_of = part.layout_of;
    for (std::size_t r = 0; r < part.runs.size(); ++r)
      o.normalized.push_back(o.fit[static_cast<std::size_t>(part.layout_of[r])]->normalized(run_values(part.runs[r])));
  }
  return out;
}

/// The signature columns of run r at grid point k: its layout's, or for a
/// run that stopped early that layout's first rows and the estimates (the
/// normalized values are affine in the data, row by row).
/// `scratch` holds the assembled columns of a shortened run (the layout's
/// own are returned without a copy).
const Eigen::MatrixXd& signature_of(const CandidateSums& s, int k, int r, Eigen::MatrixXd& scratch) {
  const Eigen::MatrixXd& Z =
      s.signature[static_cast<std::size_t>(k)][static_cast<std::size_t>(s.layout_of[static_cast<std::size_t>(r)])];
  const Eigen::Index size = s.normalized[static_cast<std::size_t>(r)].size();
  if (size == Z.rows()) return Z;
  const auto L = static_cast<std::size_t>(s.layout_of[static_cast<std::size_t>(r)]);
  const auto estimates = static_cast<Eigen::Index>(s.fit[L]->estimate_x_columns().size());
  scratch.resize(size, Z.cols());
  scratch << Z.topRows(size - estimates), Z.bottomRows(estimates);
  return scratch;
}

/// Least squares over the multiset `runs` of the normalized values on the
/// signature columns; beyond its limit a signature is held at the limit (and flagged).
Eigen::VectorXd least_squares_amplitudes(const CandidateSums& s, int k, const std::vector<int>& runs) {
  Eigen::MatrixXd scratch;
  const Eigen::Index m = signature_of(s, k, runs.front(), scratch).cols();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
  for (int r : runs) {
    const Eigen::MatrixXd& Z = signature_of(s, k, r, scratch);
    A += Z.transpose() * Z;
    b += Z.transpose() * s.normalized[static_cast<std::size_t>(r)];
  }
  // A signature the layout cannot see (a zero column) gets amplitude 0.
  return A.completeOrthogonalDecomposition().solve(b).cwiseMax(-s.amplitude_limit).cwiseMin(s.amplitude_limit);
}

}  // namespace

CandidateSums evaluate_candidate(const runs::PreparedRuns& p, const Candidate& c,
                                 const std::vector<std::vector<runs::Extension>>& selected,
                                 const NullCalibration& m0, const std::vector<std::vector<int>>& groups) {
  const runs::PreparedRuns* parts[] = {&p};
  return std::move(evaluate_candidate(parts, c, selected, m0, {groups}).front());
}

std::vector<CandidateSums> evaluate_candidate(std::span<const runs::PreparedRuns* const> parts, const Candidate& c,
                                              const std::vector<std::vector<runs::Extension>>& selected,
                                              const NullCalibration& m0,
                                              const std::vector<std::vector<std::vector<int>>>& groups) {
  INSMC_ASSERT(!parts.empty() && groups.size() == parts.size(), "{} parts, {} group lists", parts.size(), groups.size());
  auto build = std::make_shared<LayoutExtensions>(*parts.front());
  return c.amplitude_indices().empty() ? evaluate_on_grid(parts, c, selected, std::move(build), m0, groups)
                                       : evaluate_amplitudes(parts, c, selected, *build);
}

void keep_keyed_at(CandidateSums& s, std::vector<int> grid) {
  if (s.amplitudes) return;
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  std::erase_if(grid, [&](int k) {
    INSMC_ASSERT(k >= 0 && k < s.grid_size() && s.evaluated[static_cast<std::size_t>(k)],
                 "grid point {} of {} was not evaluated", k, s.grid_size());
    return s.keyed_kept[static_cast<std::size_t>(k)];
  });
  if (!grid.empty()) s.reevaluate(s, grid);
}

RunSet run_set_under(const CandidateSums& s, const std::vector<int>& runs, const std::vector<Choice>& choices) {
  std::vector<runs::GroupSums> sums(runs.size());
  Eigen::MatrixXd keyed(s.keys->size(), static_cast<Eigen::Index>(runs.size()));
  for (std::size_t j = 0; j < runs.size(); ++j) {
    const auto r = static_cast<std::size_t>(runs[j]);
    const Choice& choice = choices[j];
    if (!s.amplitudes) {
      INSMC_ASSERT(s.keyed_kept[static_cast<std::size_t>(choice.grid)], "grid point {}'s keyed values were not kept",
                   choice.grid);
      const EvaluatedRuns& e = s.at[static_cast<std::size_t>(choice.grid)];
      sums[j] = e.sums[r];
      keyed.col(static_cast<Eigen::Index>(j)) = e.keyed.col(static_cast<Eigen::Index>(r));
      continue;
    }
    const int L = s.layout_of[r];
    const runs::RunAnalyser& a = *s.fit[static_cast<std::size_t>(L)];
    Eigen::MatrixXd scratch;
    const Eigen::VectorXd v = s.normalized[r] - signature_of(s, choice.grid, runs[j], scratch) * choice.amplitude;
    sums[j] = a.sums_of(v);
    keyed.col(static_cast<Eigen::Index>(j)) = runs::keyed_values(v, a, L, *s.keys);
  }
  return make_run_set(std::move(sums), keyed, *s.keys);
}

RunsUnderChoice::RunsUnderChoice(const CandidateSums& sums, std::vector<int> runs_in) : s(&sums), runs(std::move(runs_in)) {
  if (!s->amplitudes) return;
  std::map<int, int> index;
  for (int r : runs) {
    auto [it, added] = index.emplace(r, static_cast<int>(distinct.size()));
    if (added) distinct.push_back(r);
    at.push_back(it->second);
  }
}

double RunsUnderChoice::gap_at(int k, const NullCalibration& m0, Choice* choice) const {
  Choice here{k, {}};
  double g = 0;
  if (s->amplitudes) {
    // Amplitudes by least squares on the multiset; G over its distinct runs
    // each counted as often as it is drawn.
    here.amplitude = least_squares_amplitudes(*s, k, runs);
    g = gap_value(run_set_under(*s, distinct, std::vector<Choice>(distinct.size(), here)), at, m0);
  } else {
    if (!s->evaluated[static_cast<std::size_t>(k)]) return std::numeric_limits<double>::infinity();
    g = gap_value(s->sets[static_cast<std::size_t>(k)], runs, m0);
  }
  if (choice) *choice = std::move(here);
  return g;
}

Choice choose(const CandidateSums& s, const std::vector<int>& runs, const NullCalibration& m0) {
  return choose(RunsUnderChoice(s, runs), m0);
}

Choice choose(const RunsUnderChoice& under, const NullCalibration& m0) {
  Choice best, here;
  double best_gap = std::numeric_limits<double>::infinity();
  for (int k = 0; k < under.grid_size(); ++k) {
    const double g = under.gap_at(k, m0, &here);
    if (g < best_gap) best_gap = g, best = here;
  }
  return best;
}

std::vector<double> parameter_values(const Candidate& c, const Choice& choice) {
  std::vector<double> v = c.grid_point(choice.grid);
  const std::vector<int> amp = c.amplitude_indices();
  for (std::size_t j = 0; j < amp.size(); ++j) v[static_cast<std::size_t>(amp[j])] = choice.amplitude[static_cast<Eigen::Index>(j)];
  return v;
}

}  // namespace insmc::gap
