#pragma once
/// The reports of `insmc run` (montecarlo/report/report.h): a study's
/// envelope (envelope.csv, envelope_grid.csv, envelope.md, run.json and the
/// envelope figure) and a sweep's (sweep.csv, sweep.md, sweep.json and the
/// sweep figure). Stdout: the summary, the full envelope (--full),
/// envelope.csv / sweep.csv (csv) or run.json / sweep.json (json).
#include <cstdint>
#include <string>
#include <vector>

#include "montecarlo/report/report.h"
#include "montecarlo/study/engine/block_ranges.h"
#include "montecarlo/study/run/sweep_study.h"
#include "montecarlo/study/write/study_writer.h"

namespace insmc::mc {

ReportOutline envelope_report_outline();

/// What run.json says of the run besides its envelope.
struct RunFacts {
  Json settings;                        ///< the settings with the arguments that made the numbers
  double elapsed_s = 0;                 ///< the study's wall time
  std::uint64_t resumed_from_sample = 0;
  int ranks = 0;                        ///< MPI ranks, 0 when not distributed
  std::vector<BlockSet> shares;         ///< each rank's blocks in this run (distributed)
};

Report envelope_report(const StudyConfig& config, EnvelopeFiles files, const RunFacts& facts);

ReportOutline sweep_report_outline();

/// What the sweep's summary line says of it.
struct SweepFacts {
  std::vector<std::string> swept;  ///< the swept quantities' names
  std::size_t points = 0;
  double elapsed_s = 0;
};

/// `settings`: run.json's settings, kept in sweep.json.
Report sweep_report(const StudyConfig& config, SweepFiles files, const Json& settings, const SweepFacts& facts,
                    LengthUnit unit);

}  // namespace insmc::mc
