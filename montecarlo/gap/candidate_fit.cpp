#include "montecarlo/gap/candidate_fit.h"

#include <limits>

namespace insmc::mc {

int PreparedRuns::layout_index(const gap::Layout& layout) {
  for (std::size_t i = 0; i < layouts.size(); ++i)
    if (layouts[i] == layout) return static_cast<int>(i);
  layouts.push_back(layout);
  bases.push_back(gap::make_base_model(layout, site, x_var));
  return static_cast<int>(layouts.size() - 1);
}

Eigen::VectorXd run_values(const gap::RunData& run) {
  return Eigen::Map<const Eigen::VectorXd>(run.values.data(), static_cast<Eigen::Index>(run.values.size()));
}

namespace {

std::vector<const gap::Extension*> pointers(const std::vector<gap::Extension>& selected, const gap::Extension* added) {
  std::vector<const gap::Extension*> e;
  for (const gap::Extension& s : selected) e.push_back(&s);
  if (added) e.push_back(added);
  return e;
}

bool used(const PreparedRuns& p, std::size_t L) {
  return std::find(p.layout_of.begin(), p.layout_of.end(), static_cast<int>(L)) != p.layout_of.end();
}

CandidateSums evaluate_on_grid(const PreparedRuns& p, const gap::Candidate& c,
                               const std::vector<std::vector<gap::Extension>>& selected,
                               std::vector<gap::LayoutContext>& ctx) {
  CandidateSums out;
  out.at.resize(static_cast<std::size_t>(c.grid_size()));
  for (int k = 0; k < c.grid_size(); ++k) {
    const std::vector<double> theta = c.grid_point(k);
    std::vector<gap::GroupSums>& sums = out.at[static_cast<std::size_t>(k)];
    sums.resize(p.runs.size());
    for (std::size_t L = 0; L < p.layouts.size(); ++L) {
      if (!used(p, L)) continue;
      const gap::Extension e = c.build(ctx[L], theta);
      const gap::RunAnalyser analyser(p.layouts[L], gap::combine(p.bases[L], pointers(selected[L], &e)));
      for (std::size_t r = 0; r < p.runs.size(); ++r)
        if (p.layout_of[r] == static_cast<int>(L)) sums[r] = analyser.analyse(run_values(p.runs[r]));
    }
  }
  return out;
}

CandidateSums evaluate_amplitudes(const PreparedRuns& p, const gap::Candidate& c,
                                  const std::vector<std::vector<gap::Extension>>& selected,
                                  std::vector<gap::LayoutContext>& ctx) {
  CandidateSums out;
  out.amplitudes = true;
  out.layout_of = p.layout_of;
  out.fit.resize(p.layouts.size());
  for (std::size_t L = 0; L < p.layouts.size(); ++L)
    if (used(p, L)) out.fit[L].emplace(p.layouts[L], gap::combine(p.bases[L], pointers(selected[L], nullptr)));
  for (std::size_t r = 0; r < p.runs.size(); ++r)
    out.normalized.push_back(out.fit[static_cast<std::size_t>(p.layout_of[r])]->normalized(run_values(p.runs[r])));
  const std::vector<int> amp = c.amplitude_indices();
  out.amplitude_limit.resize(static_cast<Eigen::Index>(amp.size()));
  for (std::size_t j = 0; j < amp.size(); ++j)
    out.amplitude_limit[static_cast<Eigen::Index>(j)] = c.parameters[static_cast<std::size_t>(amp[j])].grid.front();
  out.signature.resize(static_cast<std::size_t>(c.grid_size()));
  for (int k = 0; k < c.grid_size(); ++k) {
    out.signature[static_cast<std::size_t>(k)].resize(p.layouts.size());
    for (std::size_t L = 0; L < p.layouts.size(); ++L) {
      if (!used(p, L)) continue;
      Eigen::MatrixXd& Z = out.signature[static_cast<std::size_t>(k)][L];
      for (std::size_t j = 0; j < amp.size(); ++j) {
        // The signature of amplitude j alone, at unit size (SI).
        std::vector<double> theta = c.grid_point(k);
        theta[static_cast<std::size_t>(amp[j])] = 1.0;  // unit size (SI)
        const gap::Extension e = c.build(ctx[L], theta);
        const Eigen::VectorXd z = out.fit[L]->normalized_linear(e.mean);
        if (Z.size() == 0) Z.resize(z.size(), static_cast<Eigen::Index>(amp.size()));
        Z.col(static_cast<Eigen::Index>(j)) = z;
      }
    }
  }
  return out;
}

Eigen::VectorXd least_squares_amplitudes(const CandidateSums& s, int k, const std::vector<int>& runs) {
  const Eigen::Index m = s.signature[static_cast<std::size_t>(k)][static_cast<std::size_t>(s.layout_of[static_cast<std::size_t>(runs.front())])].cols();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
  for (int r : runs) {
    const Eigen::MatrixXd& Z = s.signature[static_cast<std::size_t>(k)][static_cast<std::size_t>(s.layout_of[static_cast<std::size_t>(r)])];
    A += Z.transpose() * Z;
    b += Z.transpose() * s.normalized[static_cast<std::size_t>(r)];
  }
  // A signature the layout cannot see (a zero column) gets amplitude 0.
  return A.completeOrthogonalDecomposition().solve(b);
}

}  // namespace

CandidateSums evaluate_candidate(const PreparedRuns& p, const gap::Candidate& c,
                                 const std::vector<std::vector<gap::Extension>>& selected) {
  std::vector<gap::LayoutContext> ctx(p.layouts.size());
  for (std::size_t L = 0; L < p.layouts.size(); ++L) ctx[L] = {&p.layouts[L], &p.site, &p.bases[L], {}};
  return c.amplitude_indices().empty() ? evaluate_on_grid(p, c, selected, ctx)
                                       : evaluate_amplitudes(p, c, selected, ctx);
}

gap::GroupSums run_sums(const CandidateSums& s, const Choice& choice, int r) {
  const auto ri = static_cast<std::size_t>(r);
  if (!s.amplitudes) return s.at[static_cast<std::size_t>(choice.grid)][ri];
  const auto L = static_cast<std::size_t>(s.layout_of[ri]);
  const Eigen::MatrixXd& Z = s.signature[static_cast<std::size_t>(choice.grid)][L];
  return s.fit[L]->sums_of(s.normalized[ri] - Z * choice.amplitude);
}

Choice choose(const CandidateSums& s, const std::vector<int>& runs, const gap::NullCalibration& m0) {
  Choice best;
  double best_gap = std::numeric_limits<double>::infinity();
  std::vector<gap::GroupSums> sums(s.amplitudes ? s.normalized.size() : 0);
  for (int k = 0; k < s.grid_size(); ++k) {
    double g = 0;
    Choice here{k, {}};
    if (s.amplitudes) {
      // Beyond its limit a signature is held at the limit (and flagged).
      here.amplitude = least_squares_amplitudes(s, k, runs).cwiseMax(-s.amplitude_limit).cwiseMin(s.amplitude_limit);
      for (int r : runs) sums[static_cast<std::size_t>(r)] = run_sums(s, here, r);
      g = gap::gap_value(gap::pooled(sums, runs), m0);
    } else {
      g = gap::gap_value(gap::pooled(s.at[static_cast<std::size_t>(k)], runs), m0);
    }
    if (g < best_gap) best_gap = g, best = here;
  }
  return best;
}

std::vector<double> parameter_values(const gap::Candidate& c, const Choice& choice) {
  std::vector<double> v = c.grid_point(choice.grid);
  const std::vector<int> amp = c.amplitude_indices();
  for (std::size_t j = 0; j < amp.size(); ++j) v[static_cast<std::size_t>(amp[j])] = choice.amplitude[static_cast<Eigen::Index>(j)];
  return v;
}

}  // namespace insmc::mc
