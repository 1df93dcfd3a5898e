#pragma once
/// `insmc compensate` (docs/compensate.md): for each unit (a run of a record
/// file), its estimates, each scheme's compensation and the position error
/// after it (this unit's and the population's), the scheme to use at the
/// flight time, and go / no-go against the user's limits.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "montecarlo/records/compensate/unit_prediction.h"
#include "montecarlo/report/length_unit.h"

namespace insmc::compensate {

/// A limit on the position error after the scheme, at a time on its clock.
struct PositionLimit {
  enum class Component { kHorizontal, kX, kY, kZ };
  Component component = Component::kHorizontal;
  double t_s = 0.0;
  double limit_m = 0.0;
  std::string text;  ///< as the user wrote it
};
std::string_view to_string(PositionLimit::Component c);

/// Flight and limit times on the scheme's clock: the report's flights last
/// 84 min; 12 h is longer than any preflight-compensated flight.
inline constexpr double kMaxFlightTimeS = 12 * 3600.0;

struct CompensateOptions {
  UncertaintyModel prior;
  std::vector<Scheme> schemes;          ///< candidates, in registry order
  double flight_time_s = 84 * 60.0;     ///< on each scheme's clock
  std::vector<PositionLimit> limits;
  double risk = 0.01;                   ///< largest acceptable probability of exceeding a limit
  double realignment_duration_s = 600.0;
  std::optional<std::int64_t> run;      ///< one run, or every run
  std::optional<double> site_gravity_mps2;  ///< the site's specific force (read_unit_records)
  mc::LengthUnit units = mc::LengthUnit::kMetre;    ///< of the roll-up and the verdicts (SI inside)
};

/// Checks every setting's range; throws InputError naming the option of
/// `insmc compensate` that sets it.
void validate(const CompensateOptions& options);

struct LimitCheck {
  PositionLimit limit;
  double rms_m = 0.0;               ///< this unit's RMS of the component at the limit's time
  double probability = 0.0;         ///< of exceeding the limit
  bool within() const;              ///< probability ≤ risk (set by compensate)
  double risk = 0.0;
  /// The limit over the RMS: how far the limit lies beyond the error's
  /// spread (a dimensionless margin, comparable across limits).
  double ratio() const { return limit.limit_m / std::max(rms_m, 1e-300); }
};

/// One scheme held against every limit.
struct SchemeAgainstLimits {
  Scheme scheme = Scheme::kNone;
  std::vector<LimitCheck> checks;  ///< one per --limit, in their order
  bool meets_every_limit() const;
  /// The check with the least ratio limit / RMS: this scheme's worst limit.
  const LimitCheck& worst() const;
  /// The largest probability of exceeding over the limits.
  double worst_probability() const;
};

/// Below this probability the unit's test rows are taken not to fit the
/// model (UnitPosterior::consistency_p): its predictions are then not to be
/// trusted and no verdict can be go.
inline constexpr double kInconsistentP = 1e-6;

/// How the scheme to use was chosen (docs/compensate.md, "The scheme to use").
enum class SchemeChoice {
  kLeastRmsAtFlightTime,  ///< no --limit: the least horizontal RMS at --flight-time
  kMostMarginOverLimits,  ///< with --limit: among the schemes meeting every limit, the largest worst ratio limit/RMS
  kNoneMeetsTheLimits,    ///< with --limit, none meets them all: the one coming closest (least worst P(exceed))
  kNotChosen,             ///< the test rows do not fit the model: no scheme's RMS means anything
};

struct UnitResult {
  std::int64_t run = 0;
  double consistency_chi2 = 0.0, consistency_p = 1.0;
  int consistency_dof = 0;
  ConsistencyBand consistency_band;  ///< where rows of the linear level alone put the chi-square
  bool fits_model() const { return consistency_p >= kInconsistentP; }
  /// Rows inside the model's allowance but beyond what rows of the linear
  /// level alone reach (p below kInconsistentP there): the verdict stands,
  /// the report warns.
  bool beyond_linear_level() const {
    return fits_model() && consistency_band.linear_p(consistency_chi2) < kInconsistentP;
  }
  std::vector<UnitEstimate> estimates;
  std::vector<SchemePrediction> schemes;
  SchemeChoice choice = SchemeChoice::kNotChosen;
  Scheme recommended;              ///< by `choice` (meaningless under kNotChosen)
  double recommended_rms_m = 0.0;  ///< horizontal, at the flight time
  std::optional<Scheme> runner_up;  ///< without limits: the next least RMS at the flight time
  double margin_m = 0.0;           ///< the runner-up's RMS less the recommended's
  /// With limits (and rows that fit): every scheme against every limit, in
  /// the schemes' order.
  std::vector<SchemeAgainstLimits> against_limits;
  std::vector<LimitCheck> checks;  ///< for the recommended scheme
  bool go = true;
};

struct CompensateResult {
  UnitRecords records;          ///< site, statements (the runs' data inside)
  std::vector<double> clock_s;  ///< the envelope's times
  std::vector<Identifiability> identifiability;
  std::vector<UnitResult> units;

  /// Every unit meets every limit (the command's exit code 0, else 1).
  bool all_go() const {
    return std::all_of(units.begin(), units.end(), [](const UnitResult& u) { return u.go; });
  }
};

bool is_report_time(double t_s, const CompensateOptions& options);

CompensateResult compensate(const RecordFile& file, const CompensateOptions& options);

}  // namespace insmc::compensate
