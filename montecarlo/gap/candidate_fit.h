#pragma once
/// Fitting one candidate effect (lib/gap/candidates.h) to a set of runs, the
/// step the diagnosis' ranking repeats on training halves and resamples.
/// Grid parameters are chosen by least G over their grid; amplitude
/// parameters (the size of a deterministic signature, the same in every run)
/// by least squares on the runs' normalized values, which are affine in the
/// data: z(y − S a) = z(y) − z_lin(S) a. A grid coarse enough to be cheap
/// would miss a signature seen coherently in every run by tens of percent.

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "lib/gap/candidates.h"
#include "lib/gap/gap_metric.h"
#include "lib/gap/gaussian_model.h"
#include "lib/gap/layout.h"
#include "lib/gap/run_analysis.h"

namespace insmc::mc {

/// The runs, their layouts and the base model of each layout.
struct PreparedRuns {
  gap::RecordSite site;
  std::vector<gap::RunData> runs;
  std::vector<gap::Layout> layouts;
  std::vector<int> layout_of;  // per run
  std::vector<gap::BaseModel> bases;
  UncertaintyVector x_var;

  /// Index of `layout`, added (with its base model) when new.
  int layout_index(const gap::Layout& layout);
};

Eigen::VectorXd run_values(const gap::RunData& run);

/// One candidate evaluated on every run, before any choice of parameters.
struct CandidateSums {
  bool amplitudes = false;
  /// Without amplitudes: the runs' group sums at every grid point [grid][run].
  std::vector<std::vector<gap::GroupSums>> at;
  /// With amplitudes: the fit without the candidate per layout, the runs'
  /// normalized values under it, and the normalized signature columns
  /// [grid][layout] (rows × amplitudes).
  std::vector<std::optional<gap::RunAnalyser>> fit;
  std::vector<Eigen::VectorXd> normalized;
  std::vector<std::vector<Eigen::MatrixXd>> signature;
  std::vector<int> layout_of;
  Eigen::VectorXd amplitude_limit;  ///< the largest magnitude covered, per amplitude
  int grid_size() const { return amplitudes ? static_cast<int>(signature.size()) : static_cast<int>(at.size()); }
};

/// A choice of parameters: a grid point and, for amplitude candidates, the amplitudes.
struct Choice {
  int grid = 0;
  Eigen::VectorXd amplitude;
};

/// `c` on every run of `p`, on top of the effects already selected (per layout).
CandidateSums evaluate_candidate(const PreparedRuns& p, const gap::Candidate& c,
                                 const std::vector<std::vector<gap::Extension>>& selected);

/// Run r's group sums under a choice.
gap::GroupSums run_sums(const CandidateSums& s, const Choice& choice, int r);

/// The choice of least G on `runs` (m0: the null's calibration).
Choice choose(const CandidateSums& s, const std::vector<int>& runs, const gap::NullCalibration& m0);

/// The candidate's parameter values of a choice (grid values and amplitudes).
std::vector<double> parameter_values(const gap::Candidate& c, const Choice& choice);

}  // namespace insmc::mc
