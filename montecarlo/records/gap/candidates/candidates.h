#pragma once
/// Candidate effects of the gap diagnosis (docs/gap-method.md): each a named extension
/// of the linear-Gaussian run model (gaussian_model.h) with parameters on a
/// grid. They are the diagnosis' own physics of each effect, written from
/// the effect's definition (the accelerometer error a(t) or platform angle
/// θ(t) it adds, response.h, or the prior or noise it widens), not from the
/// truth simulator; the names are those of `insmc effects` plus `bounds`
/// (priors wider than Table 3.1) and `nonlinearity` (terms the linear level
/// drops). Effects these observables cannot tell apart are one class named
/// by its members joined with `|`. One file per candidate in this folder
/// (definitions.h), listed once in candidate_list.h.
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "lib/units/quantity.h"
#include "montecarlo/records/runs/model/gaussian_model.h"

namespace insmc::gap {

/// What a candidate may use when it builds its extension for a layout.
struct LayoutContext {
  const runs::Layout* layout = nullptr;
  const runs::RecordSite* site = nullptr;
  const runs::BaseModel* base = nullptr;
  /// Unit responses already computed for this layout, by key.
  mutable std::map<std::string, Eigen::MatrixXd> cache;
};

struct CandidateParameter {
  std::string name;
  Dimension dimension;
  /// SI, ascending; for an amplitude one value: the largest magnitude the
  /// candidate covers (a fit beyond it is held there and flagged).
  std::vector<double> grid;
  /// The size of a deterministic signature: the extension's mean is linear
  /// in it, and it is fitted by least squares, not on a grid.
  bool amplitude = false;
  /// Physical limits (SI) the maximum-likelihood fit (fit/likelihood_fit.h)
  /// searches between instead of the grid, and why they are those; an
  /// amplitude's are ± the magnitude it covers (its least-squares fit is
  /// held there). A fit at a limit runs to the physics' end, not a grid's.
  double lower_si = 0.0;
  double upper_si = 0.0;
  std::string limits;
};

struct Candidate {
  std::string name;         ///< e.g. "accel_bias_instability"
  std::string description;  ///< one line
  std::vector<CandidateParameter> parameters;
  /// The extension at one point of the parameter grid (values in parameter order).
  std::function<runs::Extension(const LayoutContext&, std::span<const double>)> build;
  /// The fitted values (parameter order) in the terms `insmc effects`
  /// defines the effect by, in place, where the candidate's own differ
  /// (a transient fitted at switch-over, defined at switch-on); empty: the same.
  std::function<void(std::span<double>, const runs::RecordSite&)> to_effect_terms = {};
  /// The test that shows this effect's own signature, where records of
  /// another may look alike: said when the ranking cannot tell it from its
  /// runner-up (ranking/statements.cpp).
  std::string told_apart_by;

  /// Number of grid points (the product of the parameters' grids).
  int grid_size() const;
  /// Parameter values of grid point `index` (amplitudes 0).
  std::vector<double> grid_point(int index) const;
  /// Indices of the amplitude parameters.
  std::vector<int> amplitude_indices() const;
};

/// Every candidate, in a fixed order: the built-in ones
/// (candidate_list.h), then those registered.
const std::vector<Candidate>& candidate_registry();

/// Adds a candidate (one defined outside this library, e.g. a test's, for
/// an effect it registered with register_effect(), under the effect's
/// name). Call before any diagnosis starts (the registry is not locked);
/// throws std::logic_error on a name in use.
void register_candidate(Candidate candidate);

}  // namespace insmc::gap
