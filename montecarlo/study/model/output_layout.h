#pragma once
/// What a study reports: one output per scheme × system × time × axis, at
/// the report times (42/63/84 min) and on the envelope grid.
#include <string_view>
#include <vector>

#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

/// The a' axes of the report, and the north–east magnitude in the
/// local-level frame at time t (a' turned by the earth's rotation since t = 0).
enum class Axis { kX, kY, kZ, kHorizontal };
inline constexpr Axis kAllAxes[] = {Axis::kX, Axis::kY, Axis::kZ, Axis::kHorizontal};
std::string_view to_string(Axis a);

struct OutputSpec {
  Scheme scheme;
  System system;
  Axis axis;
  int time_index;  ///< into StudyLayout::times_s
};

struct StudyLayout {
  /// Sorted union of the report times and the grid (a report time on the
  /// grid appears once).
  std::vector<double> times_s;
  std::vector<bool> is_report_time, is_grid_time;
  /// Scheme-major, then system, time, axis.
  std::vector<OutputSpec> outputs;
  /// Per output: its place among the outputs whose per-sample values are
  /// kept (horizontal at a report time: the accuracy metrics of
  /// docs/outputs.md), or -1; n_kept of them, in output order.
  std::vector<int> kept_slot;
  int n_kept = 0;
  /// Index of the output for (scheme i, system j, time k, axis a).
  int index(int scheme_i, int system_j, int time_k, Axis a) const;
  int n_systems = 0, n_times = 0;
};

StudyLayout make_layout(const StudyConfig& config);

}  // namespace insmc::mc
