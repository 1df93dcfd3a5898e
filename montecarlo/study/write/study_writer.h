#pragma once
/// The output contract of `insmc run` and `insmc covariance` (README,
/// "Output files"): envelope.csv, envelope_grid.csv, envelope.md,
/// envelope.gp (rendered to envelope.svg and envelope.png), covariance.csv, budget.csv. Rendered to strings first, so
/// that nothing is written unless everything was computed.
#include <string>

#include "montecarlo/study/engine/engine.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/length_unit.h"
#include "montecarlo/report/plot/bar_figure.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::mc {

struct EnvelopeFiles {
  std::string envelope_csv, envelope_grid_csv, envelope_md;
  PanelFigure envelope_plot;  ///< one panel per scheme, rendered by the program (plot/panel_figure.h)
  std::string summary_text;  ///< stdout: horizontal RMS per scheme × system (envelope_summary.h)
  std::string full_text;     ///< stdout with --full: every axis and report time
  Json envelope_json;        ///< the report-time envelope for run.json
};

EnvelopeFiles render_envelope(const StudyConfig& config, const StudyLayout& layout, const StudyMap& map,
                              const StudyAccumulator& acc, LengthUnit unit);

struct CovarianceFiles {
  std::string covariance_csv, covariance_grid_csv, budget_csv, covariance_md;
  BarFigure budget_plot;  ///< the largest sources per scheme at the last report time (budget_plot.h)
  std::string summary_text;  ///< stdout: horizontal RMS per scheme × system (envelope_summary.h)
  Json covariance_json;
};

CovarianceFiles render_covariance(const StudyConfig& config, const StudyLayout& layout, const StudyMap& map,
                                  LengthUnit unit);

/// Every setting that reproduces the study (without the results).
/// One output's statistics as run.json's envelope and sweep.json's points
/// hold them (SI keys whatever the display units).
Json output_row_json(const OutputSpec& spec, double t_s, const OutputSummary& summary, double ready_time_s);

/// What a study's numbers depend on: a Monte Carlo run's settings, or a
/// covariance's (no seed, samples, threads or confidence: it has none).
enum class SettingsOf { kMonteCarlo, kCovariance };
Json settings_json(const StudyConfig& config, SettingsOf of = SettingsOf::kMonteCarlo);

}  // namespace insmc::mc
