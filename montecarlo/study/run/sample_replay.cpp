#include "montecarlo/study/run/sample_replay.h"

#include <fmt/format.h>

#include "lib/compensation/extended_vector.h"
#include "lib/uncertainty/catalogue.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::mc {

ReportOutline replay_report_outline() { return {"run", {}, {}, {ReportFormat::kMarkdown}}; }

Report replay_report(const StudyConfig& c, const StudyLayout& l, const StudyMap& map, std::uint64_t index) {
  std::string text;
  const UncertaintyVector x = Sampler(c.uncertainties).draw(c.seed, index);
  text += fmt::format("# sample {} (seed {}, fidelity {})\n\nuncertainty,value_si\n", index, c.seed, to_string(c.fidelity));
  for (const auto& spec : catalogue()) text += fmt::format("{},{}\n", spec.name, format_number(x[spec.index]));
  Eigen::MatrixXd xm = x, z(z_slot::kDim, 1);
  for (std::size_t j = 0; j < c.systems.size(); ++j) {
    map.pipeline(static_cast<int>(j)).extended_vectors(index, 1, xm, z);
    text += fmt::format("\nsystem {}: estimates and measurements (fitted {})\nquantity,x,y,z\n", system_number(c.systems[j]),
               map.fitted_terms(static_cast<int>(j)));
    for (int q = 0; q < z_slot::kSlotCount; ++q) {
      const ExtendedSlot& slot = z_slot::kSlots[q];
      std::string row = fmt::format("{}{}", slot.name, slot.unit.empty() ? "" : fmt::format(" [{}]", slot.unit));
      for (int i = z_slot::slot_start(q); i < z_slot::slot_start(q + 1); ++i) row += fmt::format(",{}", format_number(z(i, 0)));
      text += fmt::format("{}\n", row);
    }
  }
  const std::vector<double> out = evaluate_sample(c, map, l, index, x);
  text += fmt::format("\nscheme,system,clock,axis,t_min,error_m\n");
  for (size_t o = 0; o < l.outputs.size(); ++o) {
    const auto& s = l.outputs[o];
    if (!l.is_report_time[s.time_index]) continue;
    text += fmt::format("{},{},{},{},{},{}\n", to_string(s.scheme), system_number(s.system), clock_of(s.scheme),
               to_string(s.axis), format_number(l.times_s[s.time_index] / 60), format_number(out[o]));
  }
    Report report(replay_report_outline());
  report.shown(ReportFormat::kMarkdown, std::move(text));
  return report;
}

}  // namespace insmc::mc
