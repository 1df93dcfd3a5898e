#pragma once
/// The distribution of each uncertainty for a study: Table 3.1's bound and a
/// distribution per catalogue entry (uniform within ±bound by default;
/// truncated normal with bound = kσ; a fixed value; zero), with the
/// --bound NAME=VALUE and --dist NAME=SPEC overrides applied in order.
#include <array>
#include <string>
#include <string_view>

#include "lib/uncertainty/catalogue.h"

namespace insmc {

enum class DistributionKind { kUniform, kTruncatedNormal, kFixed, kZero };

struct ParameterDistribution {
  DistributionKind kind = DistributionKind::kUniform;
  double bound_si = 0.0;        ///< ±bound of uniform / truncation of normal, ≥ 0
  double sigmas_in_bound = 3.0; ///< k of normal:K (bound = kσ), > 0
  double fixed_si = 0.0;        ///< value of fixed:VALUE

  double mean() const;      ///< E[x] (SI)
  double variance() const;  ///< Var[x] (SI²)
  double fourth_central_moment() const;  ///< E[(x − E x)⁴] (for exact CI bounds)
  std::string describe() const;          ///< e.g. "uniform ±10meru"
};

class UncertaintyModel {
 public:
  /// Table 3.1 bounds, uniform everywhere.
  UncertaintyModel();

  /// "NAME=VALUE": NAME a catalogue name, group or `all`; VALUE with its unit.
  /// Of a comma list (a sweep, expanded by the caller) the first value applies.
  void apply_bound(std::string_view assignment);
  /// "NAME=uniform|normal:K|fixed:VALUE|zero".
  void apply_dist(std::string_view assignment);

  const ParameterDistribution& at(int index) const { return params_[index]; }
  ParameterDistribution& at(int index) { return params_[index]; }

  UncertaintyVector mean() const;
  UncertaintyVector variance() const;
  UncertaintyVector fourth_central_moment() const;

 private:
  std::array<ParameterDistribution, uncertainty_slot::kDim> params_;
};

/// Splits "NAME=REST"; throws InputError naming `option` when malformed or
/// NAME selects nothing (listing the names and groups accepted).
std::pair<std::vector<int>, std::string> split_assignment(std::string_view assignment,
                                                          std::string_view option);

}  // namespace insmc
