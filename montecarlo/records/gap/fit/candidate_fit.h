#pragma once
/// Fitting one candidate effect (candidates/candidates.h) to a set of runs, the
/// step the diagnosis' ranking repeats on training halves and resamples.
/// Grid parameters are chosen by least G over their grid; amplitude
/// parameters (the size of a deterministic signature, the same in every run)
/// by least squares on the runs' normalized values, which are affine in the
/// data: z(y − S a) = z(y) − z_lin(S) a. A grid coarse enough to be cheap
/// would miss a signature seen coherently in every run by tens of percent.

#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/gap/metric/gap_metric.h"
#include "montecarlo/records/gap/metric/run_set.h"
#include "montecarlo/records/runs/prepared_runs.h"
#include "montecarlo/records/runs/model/gaussian_model.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::gap {

/// One candidate evaluated on every run, before any choice of parameters.
struct CandidateSums {
  bool amplitudes = false;
  /// Without amplitudes: every run at each grid point evaluated, and its
  /// run set (valid where `evaluated`: the points this search asked for;
  /// evaluated with other sets of runs, others may hold values too).
  /// The runs' keyed values (what a run set of runs under different points
  /// is made from) are kept only where keyed_kept: each point's are as large
  /// as the file, and a choice needs those of one or two points
  /// (keep_keyed_at re-evaluates them).
  std::vector<EvaluatedRuns> at;
  std::vector<RunSet> sets;
  std::vector<bool> evaluated;
  std::vector<bool> keyed_kept;
  /// Evaluates grid points again with their keyed values (the same bits as
  /// the first time); valid while the prepared runs (every part's, when
  /// evaluated with others), the candidate and the selected effects it was
  /// evaluated on live. Sums evaluated together share the candidate's
  /// extension cache: re-evaluate them from one thread at a time.
  std::function<void(CandidateSums&, std::span<const int>)> reevaluate;
  /// With amplitudes: the fit without the candidate per layout, the runs'
  /// normalized values under it, and the normalized signature columns
  /// [grid][layout] (rows × amplitudes).
  std::vector<std::optional<runs::RunAnalyser>> fit;
  std::vector<Eigen::VectorXd> normalized;
  std::vector<std::vector<Eigen::MatrixXd>> signature;
  std::vector<int> layout_of;
  Eigen::VectorXd amplitude_limit;  ///< the largest magnitude covered, per amplitude
  const runs::KeySpace* keys = nullptr;
  int grid_size() const { return amplitudes ? static_cast<int>(signature.size()) : static_cast<int>(at.size()); }
};

/// A choice of parameters: a grid point and, for amplitude candidates, the amplitudes.
struct Choice {
  int grid = 0;
  Eigen::VectorXd amplitude;
};

/// `c` on every run of `p`, on top of the effects already selected (per
/// layout). The first parameter of a grid candidate is searched coarse to
/// fine: every other value, then the two values next to the best on all runs
/// (m0) for each setting of the other parameters. `groups`: run sets that
/// are searched each on its own (files of null runs evaluated together: a
/// point is evaluated once on every run, each group adds the values next to
/// its own best); empty: all runs, one group.
CandidateSums evaluate_candidate(const runs::PreparedRuns& p, const Candidate& c,
                                 const std::vector<std::vector<runs::Extension>>& selected,
                                 const NullCalibration& m0, const std::vector<std::vector<int>>& groups = {});

/// The same on several sets of runs on the same layouts (the records and
/// null files simulated in their layouts; every part lives as long as any
/// result: the extensions are built on parts[0]'s lattices, whose layouts
/// the amplitude fits point into): each grid point's and layout's model built once for all of them
/// (the cost), each part searched on its own (`groups[i]` as `groups`
/// above) and seeing only the points its own search asked for, so each
/// result is what evaluate_candidate gives its part alone, bit for bit.
std::vector<CandidateSums> evaluate_candidate(std::span<const runs::PreparedRuns* const> parts, const Candidate& c,
                                              const std::vector<std::vector<runs::Extension>>& selected,
                                              const NullCalibration& m0,
                                              const std::vector<std::vector<std::vector<int>>>& groups);

/// Makes the keyed values of grid points `grid` available to run_set_under
/// (a no-op for amplitude candidates, whose values are affine in theirs).
void keep_keyed_at(CandidateSums& s, std::vector<int> grid);

/// Each run of `runs` under its own choice (e.g. the held-out runs of two
/// folds, each under the other fold's fit), as a run set in that order. The
/// choices' grid points must have their keyed values (keep_keyed_at).
RunSet run_set_under(const CandidateSums& s, const std::vector<int>& runs, const std::vector<Choice>& choices);

/// A multiset of runs (indices into the candidate's runs, repeats allowed:
/// a resample) and G on it at any grid point.
class RunsUnderChoice {
 public:
  RunsUnderChoice(const CandidateSums& s, std::vector<int> runs);
  /// G at grid point k (amplitudes by least squares on the multiset, into
  /// *choice when given); +inf at a point the search did not evaluate.
  double gap_at(int k, const NullCalibration& m0, Choice* choice = nullptr) const;
  int grid_size() const { return s->grid_size(); }

 private:
  const CandidateSums* s;
  std::vector<int> runs;
  std::vector<int> distinct, at;  ///< amplitude candidates: the distinct runs and where each entry sits among them
};

/// The choice of least G on the multiset `runs` (m0: the null's calibration).
Choice choose(const CandidateSums& s, const std::vector<int>& runs, const NullCalibration& m0);
Choice choose(const RunsUnderChoice& under, const NullCalibration& m0);

/// The candidate's parameter values of a choice (grid values and amplitudes).
std::vector<double> parameter_values(const Candidate& c, const Choice& choice);

}  // namespace insmc::gap
