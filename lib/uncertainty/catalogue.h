#pragma once
/// The uncertainty catalogue: every parameter of Table 3.1 and chapter 2, one
/// entry per scalar, with its name (as `insmc params` lists it), the paper's symbol, its
/// dimension (SI inside), its default bound, the systems it applies to and
/// whether it is drawn anew at each alignment. The single source of truth for
/// the sampler, the --bound/--dist options, `insmc params`, the error budget
/// and the Table 3.1 printout.
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"
#include "lib/uncertainty/uncertainty_vector.h"

namespace insmc {

/// Which alignment concepts a parameter acts in.
enum class Applies { kBoth, kSystem1Only };

struct UncertaintySpec {
  std::string_view name;         ///< catalogue name, e.g. "gyro_drift_x"
  std::string_view group;        ///< group prefix, e.g. "gyro_drift"
  std::string_view symbol;       ///< the paper's symbol, e.g. "ω_dox"
  int index;                     ///< slot in UncertaintyVector (uncertainty_slot::)
  Dimension dimension;           ///< SI unit family
  double default_bound_si;       ///< Table 3.1 bound (or its half: ζ, ∂f split, catalogue.cpp)
  std::string_view paper_unit;   ///< unit the paper states the bound in
  Applies applies;               ///< system(s) it acts in
  bool per_alignment;            ///< drawn anew at every alignment (ζ_r, ∂f_r)
  std::string_view source;       ///< where the bound comes from
};

/// All uncertainty_slot::kDim entries, in UncertaintyVector order.
std::span<const UncertaintySpec> catalogue();

/// The entry named `name`, or nullopt.
std::optional<UncertaintySpec> find_uncertainty(std::string_view name);

/// The group of every measurement error a compensation scheme relies on
/// (kSchemeErrorGroups below):
/// `--dist scheme_errors=zero` gives schemes with perfect measurements.
inline constexpr std::string_view kSchemeErrorsGroup = "scheme_errors";

/// The catalogue's groups that are a compensation scheme's own measurement
/// errors (chapter 5; no effect on a run without that scheme). A new one is
/// listed here: what is a scheme error follows the groups, not the slots'
/// order in UncertaintyVector.
inline constexpr std::array<std::string_view, 4> kSchemeErrorGroups = {
    "alignment_drift_error", "reset_position_error", "reset_velocity_error", "realignment_azimuth_error"};

/// A measurement error of a compensation scheme: its group is one of
/// kSchemeErrorGroups.
bool is_scheme_error(const UncertaintySpec& spec);

/// Indices selected by a catalogue name, a group prefix (e.g. "gyro_drift"
/// for its x, y, z), "scheme_errors" or "all". Empty when nothing matches.
std::vector<int> select_uncertainties(std::string_view name_or_group);

/// Distinct group names in catalogue order, then "scheme_errors".
std::vector<std::string> uncertainty_groups();

/// The physical range of an entry's bound (and of a fixed value's
/// magnitude): [0, magnitude_limit(dimension)] (lib/units/physical_range.h),
/// except the altitude error, held to 10 km (beyond it the gravity error
/// 2 g δh / R of the linear model is no longer small).
PhysicalRange bound_range(const UncertaintySpec& spec);

/// Default bound vector (SI), from the catalogue.
UncertaintyVector default_bounds();

/// The paper-unit conversion factor of an entry (SI per paper unit), used
/// only at the edges (printouts).
double paper_unit_to_si(const UncertaintySpec& spec);

}  // namespace insmc
