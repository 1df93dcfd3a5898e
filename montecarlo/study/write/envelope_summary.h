#pragma once
/// The compact table `insmc run` and `insmc covariance` print on stdout:
/// one row per scheme × system, one column per report time, the horizontal
/// RMS (what the report's schemes are judged by) and the ready time. The
/// full tables, every axis and statistic, go to the files.
#include <optional>
#include <string>
#include <vector>

namespace insmc::mc {

/// The accuracy metrics of one horizontal output, in the printed unit, with
/// the half-widths of their confidence intervals (0 for the covariance
/// level's exact values).
struct AccuracyFigures {
  double cep50 = 0, cep50_half = 0, drms2 = 0, drms2_half = 0;
  double rate_nmiph = 0, rate_half_nmiph = 0;  ///< CEP50 / t in n.mi./h
};

/// One horizontal output at a report time.
struct HorizontalPoint {
  std::string scheme, clock;
  int system = 0;
  double t_min = 0;
  double rms = 0;                    ///< in the printed unit
  std::optional<double> half_width;  ///< of its confidence interval; none for exact values
  double ready_min = 0;              ///< from the first switch-over until the vehicle may fly
  std::optional<AccuracyFigures> accuracy;
};

/// The caption, a line naming each scheme's clock (where t = 0 is), then a
/// Markdown table: scheme | sys | one "T min" column per report time | then,
/// when the points carry accuracy metrics, "CEP50 T" | "2DRMS T" |
/// "CEP/t nmi/h" (CEP50/t in n.mi./h) at the latest such time T | ready
/// (minutes). Rows and columns keep the
/// order of first appearance in `points`. Values with an interval are
/// printed "28830 ± 480" (interval_format.h), exact ones to five
/// significant figures. `caption` names the quantity and its unit.
std::string render_horizontal_summary(const std::vector<HorizontalPoint>& points, const std::string& caption);

}  // namespace insmc::mc
