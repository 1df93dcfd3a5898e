#include "montecarlo/study/model/output_layout.h"

#include <algorithm>
#include <cmath>

namespace insmc::mc {

std::string_view to_string(Axis a) {
  switch (a) {
    case Axis::kX: return "x";
    case Axis::kY: return "y";
    case Axis::kZ: return "z";
    case Axis::kHorizontal: return "horizontal";
  }
  return "?";
}

int StudyLayout::index(int scheme_i, int system_j, int time_k, Axis a) const {
  return ((scheme_i * n_systems + system_j) * n_times + time_k) * 4 + static_cast<int>(a);
}

StudyLayout make_layout(const StudyConfig& c) {
  StudyLayout l;
  std::vector<double> times = c.report_times_s;
  if (c.with_grid) {
    const int n = static_cast<int>(std::floor(c.grid_end_s / c.grid_step_s + 1e-9));
    for (int k = 0; k <= n; ++k) times.push_back(k * c.grid_step_s);
  }
  std::sort(times.begin(), times.end());
  // Merge times closer than a microsecond (a report time on the grid).
  for (double t : times)
    if (l.times_s.empty() || t - l.times_s.back() > 1e-6) l.times_s.push_back(t);
  for (double t : l.times_s) {
    bool report = false;
    for (double r : c.report_times_s) report |= std::abs(r - t) <= 1e-6;
    const double k = t / c.grid_step_s;
    l.is_report_time.push_back(report);
    l.is_grid_time.push_back(c.with_grid && std::abs(k - std::round(k)) < 1e-9 && t <= c.grid_end_s + 1e-6);
  }
  l.n_systems = static_cast<int>(c.systems.size());
  l.n_times = static_cast<int>(l.times_s.size());
  for (size_t i = 0; i < c.schemes.size(); ++i)
    for (int j = 0; j < l.n_systems; ++j)
      for (int k = 0; k < l.n_times; ++k)
        for (Axis a : kAllAxes) l.outputs.push_back({c.schemes[i], c.systems[j], a, k});
  for (const OutputSpec& o : l.outputs)
    l.kept_slot.push_back(o.axis == Axis::kHorizontal && l.is_report_time[o.time_index] ? l.n_kept++ : -1);
  return l;
}

}  // namespace insmc::mc
