#pragma once
/// The output of `insmc compensate` (docs/compensate.md): compensate.md,
/// estimates.csv, compensation.csv, envelope.csv, compensate.json and the
/// figure of each unit's horizontal envelope against the population's.
/// Rendered to strings first, so that nothing is written unless everything
/// was computed.
#include <string>

#include "montecarlo/records/compensate/compensate.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::mc {

struct CompensateFiles {
  std::string markdown, estimates_csv, compensation_csv, envelope_csv;
  std::string summary_text;  ///< stdout: one line per unit (scheme to use, margin, verdict)
  Json json;
  PanelFigure plot;
};

CompensateFiles render_compensate(const CompensateResult& result, const CompensateOptions& options,
                                  const std::string& source);

}  // namespace insmc::mc
