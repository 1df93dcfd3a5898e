#pragma once
/// One cell of a reproduced table: the value insmc computes beside the value
/// the report printed (chapter 3–5 tables, Figure 3.2 data).
#include <optional>
#include <string>

namespace insmc::tables {

struct TableCell {
  std::string table;   ///< "3.1", "4.1", "4.2", "4.3", "4.3b", "5.1", "5.2", "fig3.2"
  /// The printed row (tables/data/*.csv), followed by " [member]" when the
  /// printed row lists several uncertainties or systems and this cell is one
  /// of them (e.g. "2 | ω_doy, ω_doz | U4 [ω_doy, sys 2]").
  std::string row;
  std::string column;  ///< as printed, e.g. "10.5 min", "bound"
  std::optional<double> time_min;  ///< the column's time for fig3.2 (its x axis); absent elsewhere
  std::string unit;    ///< the printed unit, e.g. "ft/meru", "μg/PPM"
  std::optional<double> printed;        ///< the printed value; absent for fig3.2
  double computed = 0.0;                ///< in `unit`; a magnitude where the report prints one
  std::optional<double> deviation_pct;  ///< 100 (computed − printed)/printed; absent when printed is 0 or absent
  std::string note;                     ///< why the cell deviates (tables/notes/cell_notes.csv), or empty
};

}  // namespace insmc::tables
