#pragma once
/// Every printed cell of the report's Tables 3.1, 4.1, 4.2, 4.3 (with the
/// drift-threshold table after it, "4.3b"), 5.1 and 5.2, computed from the
/// model beside the printed value, and the curves of Figure 3.2 ("fig3.2").
/// What each printed row means (axis, time function, unit) and why cells
/// deviate: tables/notes/tables.md; per-cell notes: tables/notes/cell_notes.csv.
#include <array>
#include <string_view>
#include <vector>

#include "lib/common/model_options.h"
#include "tables/table_cell.h"

namespace insmc::tables {

/// Which formulas compute the cells.
enum class TableConvention {
  /// The report's own formulas, transcription slips fixed: the coefficient
  /// maps (3.22), (3.23), (3.29b–e), A1 (4.4b), the residual maps of
  /// chapter 5, the time functions of (3.29), (4.4), (4.5), (4.6).
  kPaper,
  /// Errors of the original corrected (tables/notes/errata.md): the linear
  /// model (lib/propagation/linear_model.h: g·MUY with cos L_0, full
  /// alignment solution, exact C_n^{a'}(t)) and its integrated Schuler ODE
  /// wherever the cell is an uncompensated effect of a catalogue
  /// uncertainty; the exact U5 time function (3.30); the chapter-5 residual
  /// maps with cos L_0 on g·MUY elsewhere.
  kCorrected,
};

std::string_view to_string(TableConvention c);
/// "paper" or "corrected"; throws InputError naming `field` otherwise.
TableConvention parse_table_convention(std::string_view text, std::string_view field = "convention");

/// Table ids in print order.
inline constexpr std::array<std::string_view, 8> kTableIds = {"3.1", "4.1", "4.2", "4.3",
                                                              "4.3b", "5.1", "5.2", "fig3.2"};

/// Figure 3.2 grid: 0 to 90 min every 5 min.
inline constexpr double kFigureStepMin = 5.0;
inline constexpr double kFigureEndMin = 90.0;

/// ΔV pulse weight of Table 4.3 and the thresholds after it: 0.1 ft/s (§4.3).
inline constexpr double kTable43PulseWeightFtps = 0.1;

/// A cell deviating from its printed value by more than this needs a note
/// (tables/notes/cell_notes.csv); the same bound checks the notes' claims.
inline constexpr double kNoteThresholdPct = 3.0;

/// All cells: for each printed cell one TableCell per listed uncertainty and
/// system (rows such as "1&2 | ζ_x, ζ_y | A1" expand to members, named in
/// TableCell::row), in the order of tables/data/*.csv; then the Figure 3.2
/// curves (printed empty). Computed values are in the printed unit and,
/// since the report prints magnitudes, are magnitudes (fig3.2 keeps signs).
/// Deterministic for given options. `options.latitude_rad` etc. apply; the
/// printed values are for the report's 45°.
std::vector<TableCell> compute_tables(const ModelOptions& options, TableConvention convention);

/// One checked claim of a note (tables/notes/cell_notes.csv) on one cell:
///  * kind "rounding": |computed − printed| ≤ half a unit in the last printed place;
///  * `meant` given: computed within kNoteThresholdPct of it;
///  * `alt_time_min` given: the cell computed at that time within
///    kNoteThresholdPct of the printed value;
///  * the kind is one of those documented in tables/notes/tables.md;
///  * a note applying to the convention matches at least one cell
///    (then row and column name the note, `holds` is false).
struct NoteCheck {
  std::string table, row, column, kind;
  bool holds = true;
  std::string detail;  ///< the numbers compared
};

/// The checks of every note that applies to `convention`, on every cell it matches.
std::vector<NoteCheck> check_note_claims(const ModelOptions& options, TableConvention convention);

}  // namespace insmc::tables
