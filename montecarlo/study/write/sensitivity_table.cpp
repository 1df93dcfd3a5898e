#include "montecarlo/study/write/sensitivity_table.h"

#include "lib/uncertainty/catalogue.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/interval_format.h"

namespace insmc::mc {

std::string render_sensitivity_csv(const StudyLayout& l, const StudyMap& map) {
  std::vector<std::string> header = {"scheme", "system", "t_min", "component"};
  for (const UncertaintySpec& p : catalogue()) header.emplace_back(p.name);
  Table table(header);
  static constexpr const char* kComponents[kRowsPerMap] = {"x", "y", "z", "north", "east"};
  for (std::size_t o = 0; o < l.outputs.size(); ++o) {
    const OutputSpec& spec = l.outputs[o];
    // One output per (scheme, system, time) carries the five rows: the horizontal one.
    if (spec.axis != Axis::kHorizontal || !l.is_report_time[spec.time_index]) continue;
    const Eigen::MatrixXd& m = map.transposed(map.system_index(o));
    const int base = map.row_base(o);
    for (int r = 0; r < kRowsPerMap; ++r) {
      const auto column = m.col(base + r);
      if (!column.tail(m.rows() - uncertainty_slot::kDim).isZero(0.0)) continue;  // acts on more than x
      std::vector<std::string> row = {std::string(to_string(spec.scheme)), std::to_string(system_number(spec.system)),
                                      format_number(l.times_s[spec.time_index] / 60.0), kComponents[r]};
      for (int k = 0; k < uncertainty_slot::kDim; ++k) row.push_back(format_number(column[k]));
      table.add_row(std::move(row));
    }
  }
  return render_csv(table);
}

}  // namespace insmc::mc
