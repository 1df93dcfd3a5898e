#pragma once
/// `insmc compensate` (docs/compensate.md): for each unit (a run of a record
/// file), its estimates, each scheme's compensation and the position error
/// after it (this unit's and the population's), the scheme to use at the
/// flight time, and go / no-go against the user's limits.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "montecarlo/compensate/unit_prediction.h"
#include "montecarlo/write/length_unit.h"

namespace insmc::mc {

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
  LengthUnit units = LengthUnit::kMetre;    ///< of the roll-up and the verdicts (SI inside)
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
};

/// Below this probability the unit's test rows are taken not to fit the
/// model (UnitPosterior::consistency_p): its predictions are then not to be
/// trusted and no verdict can be go.
inline constexpr double kInconsistentP = 1e-6;

struct UnitResult {
  std::int64_t run = 0;
  double consistency_chi2 = 0.0, consistency_p = 1.0;
  int consistency_dof = 0;
  bool fits_model() const { return consistency_p >= kInconsistentP; }
  std::vector<UnitEstimate> estimates;
  std::vector<SchemePrediction> schemes;
  Scheme recommended;              ///< least horizontal RMS at the flight time
  double recommended_rms_m = 0.0;
  std::optional<Scheme> runner_up;
  double margin_m = 0.0;           ///< the runner-up's RMS less the recommended's
  std::vector<LimitCheck> checks;  ///< for the recommended scheme
  bool go = true;
};

struct CompensateResult {
  UnitRecords records;          ///< site, statements (the runs' data inside)
  std::vector<double> clock_s;  ///< the envelope's times
  std::vector<Identifiability> identifiability;
  std::vector<UnitResult> units;
};

/// The times the report tabulates: 42, 63 and 84 min, the flight time and
/// the limits' times.
std::vector<double> report_times(const CompensateOptions& options);
bool is_report_time(double t_s, const CompensateOptions& options);

/// The envelope's times: every 3 min to the last report time, and the
/// report times themselves.
std::vector<double> envelope_times(const CompensateOptions& options);

CompensateResult compensate(const RecordFile& file, const CompensateOptions& options);

}  // namespace insmc::mc
