#pragma once
/// A trade-study sweep as a study: swept quantities (each a list of values
/// and how a value is set in the study), every point a full Monte Carlo
/// study, and the files of the whole (sweep.csv, the summary, the figure,
/// sweep.json's axes and points). The command line that finds the swept
/// quantities is apps/sweep.h.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/model/study_config.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/length_unit.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::mc {

struct SweepAxis {
  std::string column;                 ///< sweep.csv column, SI unit in the name (test_duration_s)
  std::vector<std::string> texts;     ///< the values as given
  std::vector<double> values_si;
  std::function<void(StudyConfig&, std::size_t)> apply;  ///< sets value i
};

/// At most 100 values per quantity and 1000 points in all (InputError
/// otherwise): every point is a full study, minutes each at the default
/// samples, so these bound a sweep's run time.
void check_sweep_size(const std::vector<SweepAxis>& axes);

/// Builds and validates the study of every point (InputError naming the
/// first bad value), before any point is run.
void check_sweep_points(const StudyConfig& base, const std::vector<SweepAxis>& axes);

/// A sweep column without its SI unit (test_duration_s → test_duration), for
/// labels that carry the unit the user typed.
std::string quantity_name(std::string_view column);

struct SweepFiles {
  std::string sweep_csv, summary_md;
  PanelFigure plot;
  Json json = Json::object();
};
/// Runs the Monte Carlo study of one point (every block, merged).
using StudyRunner = std::function<StudyAccumulator(const StudyConfig&, const StudyMap&)>;

/// Runs every point of the sweep and returns sweep.csv (each swept quantity
/// in SI and, beside it, in the unit typed), a Markdown summary (the
/// horizontal RMS at every report time per point), the plot of the
/// horizontal RMS at the last report time against the first swept quantity
/// in the units it was given in (a panel per scheme, a line per system and
/// combination of the other swept quantities), and sweep.json's axes and
/// points (SI keys whatever --units; the caller adds the settings).
/// `run`: how each point is run (default: every block in this process; under
/// MPI, apps/cmd_run.cpp splits each point's blocks over the ranks).
SweepFiles run_sweep(const StudyConfig& base, const std::vector<SweepAxis>& axes, LengthUnit unit,
                     const StudyRunner& run = {});

}  // namespace insmc::mc
