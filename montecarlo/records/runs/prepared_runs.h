#pragma once
/// The records as the run model reads them (its site completed, short
/// filter windows summed, a scheme's estimates recomputed from each run's
/// own test rows) and its runs placed on their layouts, each layout with its
/// base model: what the diagnosis, its null and `compensate` start from.
#include <Eigen/Core>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lib/records/record.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "lib/units/units.h"
#include "montecarlo/records/runs/model/gaussian_model.h"
#include "montecarlo/records/runs/model/key_space.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "montecarlo/records/runs/model/scheme_rows.h"
#include "montecarlo/records/runs/files/layout.h"
#include "montecarlo/records/runs/files/site_values.h"

namespace insmc::runs {

/// A union of layouts serves as their lattice when it holds at most this
/// many times the rows of the largest of them, or at most 1/this of the rows
/// the distinct layouts would be fitted on apart (PreparedRuns::add_lattice).
inline constexpr double kLatticeGrowth = 1.5;

/// How records are read into the run model.
struct RecordReading {
  UncertaintyModel prior;  ///< Table 3.1 unless overridden
  /// Pulse weight assumed when the header has no dv_pulse_mps and the f
  /// rows are too few to tell a lattice (site_values.h) [m/s].
  double default_pulse_mps = 0.1 * kFtpsToMps;
  ExtractionOptions extraction;
  /// f windows shorter than this are summed into windows of at least this
  /// length before anything else (records/filter_windows.h) [s].
  double min_filter_interval_s = 1.0;
};

/// The records as the run model uses them, and its site. After a scheme
/// that uses the test run, each run's estimates are recomputed from its test
/// rows (scheme_rows.h): the test rows kept are the filter grid τ..T the
/// estimates use; when a run lacks part of that grid, the navigation rows
/// cannot be conditioned on the estimates and only the test run (still
/// uncompensated) is diagnosed.
struct Records {
  RecordFile file;
  RecordSite site;
  std::vector<SchemeEstimates> estimates;  // per run, for a scheme that uses the test run
  bool navigation_dropped = false;         // the scheme's estimates could not be recomputed
};

/// The report's estimators of the records' test run (T, τ, pulse weight and
/// resolution from the completed site), with the terms `insmc run` fits
/// (resolvable_terms under `prior`); throws InputError naming the header key
/// of a test-run setting out of range.
TestRunEstimators record_estimators(const RecordSite& site, const UncertaintyModel& prior);

/// The records read: `statements` gets what the data cannot support,
/// `site_values` every value of the site with its source.
Records read_records(const RecordFile& file, const RecordReading& options, std::vector<std::string>& statements,
                     std::vector<SiteValue>& site_values);

/// The runs, their layouts and the base model of each layout.
///
/// Every layout takes its rows from a lattice (layout_union.h): the union of
/// the records' layouts when it is not much larger than they are, else the
/// layout itself. Models are built on the lattices, once, and each layout's
/// are its rows of its lattice's (select_rows), so a file whose runs each
/// miss other records costs about what one layout costs.
struct PreparedRuns {
  RecordSite site;
  std::vector<RunData> runs;
  std::vector<Layout> layouts;
  std::vector<int> layout_of;  // per run
  std::vector<Layout> lattices;
  std::vector<BaseModel> lattice_bases;  // per lattice
  std::vector<int> lattice_of;           // per layout
  std::vector<std::vector<Eigen::Index>> lattice_rows;  // per layout: its rows in its lattice
  UncertaintyVector x_var;
  KeySpace keys;  // over every layout

  /// Adds the union of `layouts` as a lattice when it holds at most
  /// kLatticeGrowth times the rows of the largest of them, or when fitting
  /// it costs at most 1/kLatticeGrowth of fitting the distinct layouts apart
  /// (each run of other software drops its own records, and runs stop at
  /// different times: the union is then larger than any one run but far
  /// smaller than their fits apart). A union of layouts that share few rows
  /// would cost more than they do.
  void add_lattice(std::span<const Layout* const> layouts);

  /// Layout L's base model: its rows of its lattice's, made when asked (one
  /// kept per layout would hold the file's rows once more per layout).
  BaseModel base_of(int layout) const;

  /// Takes the scheme's use of a run's own test-run estimates off its rows
  /// (scheme_rows.h), the run analysed under `layout`: exact, whatever moved
  /// the estimates.
  void take_off_estimates(RunData& run, int layout, const SchemeEstimates& estimates) const;

  /// Index of `layout`, added (with its lattice rows and keys) when new.
  int layout_index(const Layout& layout);
  /// Index of the layout `run` is analysed under: its own, or a known
  /// layout it is the beginning of (rows_begun; the run then loses the
  /// last r row that layout lacks), else its own, added.
  int place(RunData& run);
};

/// The records' runs on their layouts, each layout with its base model, the
/// scheme's estimates taken off.
PreparedRuns prepare(const Records& records, const RecordReading& options);

/// The analyser of every layout of `p` under its lattice's base model with
/// `extensions[l]` (built on lattice l; empty: none), the lattice's fit made
/// once and each layout's cut from it (run_analysis.h). Layouts no run uses
/// (`used[L]` false, when `used` is given) are left empty.
std::vector<std::optional<RunAnalyser>> layout_analysers(const PreparedRuns& p,
                                                         const std::vector<std::vector<const Extension*>>& extensions,
                                                         const std::vector<bool>& used = {});

/// The same analysers one at a time: each built, handed to `use(L, analyser)` (which may keep it)
/// and dropped before the next (layouts in index order within each
/// lattice), so that at most one layout's model is held at a time (a file
/// whose runs each drop their own records has a layout per run).
void for_each_layout_analyser(const PreparedRuns& p, const std::vector<std::vector<const Extension*>>& extensions,
                              const std::vector<bool>& used,
                              const std::function<void(std::size_t layout, RunAnalyser&& analyser)>& use);

/// A run's row values as a vector.
Eigen::VectorXd run_values(const RunData& run);

}  // namespace insmc::runs
