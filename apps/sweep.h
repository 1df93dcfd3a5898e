#pragma once
/// Trade-study sweeps: any option given a comma list (--test-duration
/// 5min,10min,15min, --bound gyro_drift=1meru,3meru,10meru,
/// --realignment-duration 5min,15min, ...) is a swept quantity; several
/// sweep over their Cartesian product. Each point is a full study.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "apps/cli_common.h"
#include "montecarlo/engine/engine.h"
#include "montecarlo/study/study_config.h"
#include "montecarlo/write/json.h"
#include "montecarlo/write/length_unit.h"
#include "montecarlo/write/plot/panel_figure.h"

namespace insmc::app {

struct SweepAxis {
  std::string column;                 ///< sweep.csv column, SI unit in the name (test_duration_s)
  std::vector<std::string> texts;     ///< the values as given
  std::vector<double> values_si;
  std::function<void(mc::StudyConfig&, std::size_t)> apply;  ///< sets value i
};

/// The swept quantities of the command line (empty: no sweep).
std::vector<SweepAxis> find_sweeps(const po::variables_map& vm);

/// For the subcommands that take one value of each quantity: a comma list
/// in a sweepable option is refused (InputError) instead of its first value
/// being used.
void refuse_sweeps(const po::variables_map& vm, const std::string& subcommand);

/// Builds and validates the study of every point (InputError naming the
/// first bad value), before any point is run.
void check_sweep_points(const mc::StudyConfig& base, const std::vector<SweepAxis>& axes);

/// Runs every point of the sweep and returns sweep.csv, a Markdown summary,
/// the plot of the horizontal RMS at the last report time against the first
/// swept quantity in the units it was given in (a panel per scheme, a line
/// per system and combination of the other swept quantities), and sweep.json's axes and points (SI keys whatever
/// --units; the caller adds the settings).
/// A sweep column without its SI unit (test_duration_s → test_duration), for
/// labels that carry the unit the user typed.
std::string quantity_name(std::string_view column);

struct SweepFiles {
  std::string sweep_csv, summary_md;
  mc::PanelFigure plot;
  mc::Json json = mc::Json::object();
};
/// Runs the Monte Carlo study of one point (every block, merged).
using StudyRunner = std::function<mc::StudyAccumulator(const mc::StudyConfig&, const mc::StudyMap&)>;
/// `run`: how each point is run (default: every block in this process; under
/// MPI, apps/cmd_run.cpp splits each point's blocks over the ranks).
SweepFiles run_sweep(const mc::StudyConfig& base, const std::vector<SweepAxis>& axes, mc::LengthUnit unit,
                     const StudyRunner& run = {});

}  // namespace insmc::app
