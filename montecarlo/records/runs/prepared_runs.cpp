#include "montecarlo/records/runs/prepared_runs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "montecarlo/records/runs/files/filter_windows.h"
#include "montecarlo/records/runs/files/layout_union.h"
#include "montecarlo/records/runs/files/site_values.h"

namespace insmc::runs {

TestRunEstimators record_estimators(const RecordSite& site, const UncertaintyModel& prior) {
  const TestRunOptions test = record_test_options(site);
  // A recorder's filter interval need not divide T: the fits take the K =
  // ⌊T/τ⌋ windows that end within the test run, and (5.10) still carries
  // the fit to T; the settings are checked over the span those windows cover.
  TestRunOptions covered = test;
  if (test.intervals() >= 1) covered.duration_s = test.intervals() * test.filter_interval_s;
  try {
    validate(covered);
  } catch (const InputError& e) {
    // The values come from the records' header, not from an option:
    // name the header key the test-run setting was read from.
    std::string key = e.field();
    for (const auto& [option, header_key] :
         {std::pair{"--test-duration", "test_duration_s"}, std::pair{"--filter-interval", "filter_interval_s"},
          std::pair{"--dv-pulse", "dv_pulse_mps"}, std::pair{"--position-resolution", "position_resolution_m"}})
      if (key == option) key = header_key;
    throw InputError(fmt::format("records' header {} (the test run the estimates come from)", key),
                     e.value(), e.allowed());
  }
  const Resolvability resolvable = resolvable_terms(site.system, site.model, test, prior);
  return make_estimators(test, site.model, resolvable.u3, resolvable.u4);
}

Records read_records(const RecordFile& file, const RecordReading& options, std::vector<std::string>& statements,
                     std::vector<SiteValue>& site_values) {
  Records r{file, {}, {}};
  const RecordHeader header = file.header.without_truth();
  r.site = read_site(header, options.default_pulse_mps);
  // What the header leaves out is inferred from the rows and said: the null
  // is simulated with these values.
  site_values = complete_site(RecordFile{header, file.runs}, r.site, options.default_pulse_mps);
  for (const SiteValue& v : site_values)
    if (v.source != "header") statements.push_back(v.reason);
  // A stamp that jitters about the windows' grid is its window's time, for
  // the model's rows and the null runs alike: each run's own jitter would
  // otherwise make every run a layout of its own (a model per run, ten
  // times the cost of a 20-run file). A row moved only where it stays
  // between its neighbours.
  const double grid_s = r.site.filter_interval_s;
  for (RecordRun& run : r.file.runs)
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      double& t = run.rows[i].t_s;
      const double on_grid = std::round(t / grid_s) * grid_s;
      const double off = std::abs(t - on_grid);
      if (off > kMaxStampJitter * grid_s || off <= 1e-9 * grid_s) continue;
      if ((i == 0 || run.rows[i - 1].t_s < on_grid) && (i + 1 == run.rows.size() || on_grid < run.rows[i + 1].t_s))
        t = on_grid;
    }
  r.file.header.set(std::string(kKeyDvPulseMps), r.site.dv_pulse_mps);
  r.file.header.set(std::string(kKeyPositionResolutionM), r.site.position_resolution_m);
  // After a scheme that uses the test run, the windows stay as recorded:
  // its estimates came from them, and an estimator of longer windows can
  // differ by a window's counting noise (5.3's Δf̂(T)).
  if (uses_test_run(r.site.scheme) && r.site.filter_interval_s < options.min_filter_interval_s)
    statements.push_back(fmt::format(
        "f is recorded over {:g} s windows and kept so: scheme {}'s estimates were made from them (the diagnosis "
        "takes longer than with windows of {:g} s or more)",
        r.site.filter_interval_s, to_string(r.site.scheme), options.min_filter_interval_s));
  const FilterWindows windows =
      uses_test_run(r.site.scheme) ? FilterWindows{r.site.filter_interval_s, 1, 0}
                                   : coarsen_filter_windows(r.file, r.site.filter_interval_s,
                                                                 r.site.test_duration_s, options.min_filter_interval_s);
  if (windows.factor > 1) {
    statements.push_back(fmt::format(
        "f is recorded over {:g} s windows: they are summed {} at a time into {:g} s windows (what a {:g} s filter "
        "box counts; nothing the model looks for lies above {:g} Hz){}",
        r.site.filter_interval_s, windows.factor, windows.tau_s, windows.tau_s, 0.5 / windows.tau_s,
        windows.dropped > 0 ? fmt::format("; {} f values in blocks with a gap are left out", windows.dropped) : ""));
    r.site.filter_interval_s = windows.tau_s;
    r.file.header.set("filter_interval_s", windows.tau_s);
  }
  const Scheme scheme = r.site.scheme;
  if (!uses_test_run(scheme)) return r;
  r.site.estimators = record_estimators(r.site, options.prior);
  for (const RecordRun& run : file.runs) {
    const std::optional<SchemeEstimates> u = record_estimates(run, r.site, *r.site.estimators);
    if (!u) {
      statements.push_back(fmt::format(
          "run {} lacks part of the test run's filter grid (f and r at every {:g} s up to T = {:g} s), from which "
          "the scheme's estimates are recomputed: the navigation rows after scheme {} cannot be modelled, so only "
          "the test runs are diagnosed", run.id, r.site.filter_interval_s, r.site.test_duration_s, to_string(scheme)));
      for (RecordRun& kept : r.file.runs)
        std::erase_if(kept.rows, [](const RecordRow& row) { return row.phase != Phase::kTest; });
      r.file.header.set(std::string(kKeyScheme), std::string(to_string(Scheme::kNone)));
      r.site.scheme = Scheme::kNone;
      r.site.estimators.reset();
      r.estimates.clear();
      r.navigation_dropped = true;
      return r;
    }
    r.estimates.push_back(*u);
  }
  // The test rows the estimates used, and no others (the null runs are
  // simulated on the same rows).
  const double tau = r.site.filter_interval_s;
  for (RecordRun& run : r.file.runs)
    std::erase_if(run.rows, [&](const RecordRow& row) {
      const double k = row.t_s / tau;
      return row.phase == Phase::kTest && std::abs(k - std::round(k)) > 1e-6;
    });
  return r;
}

BaseModel PreparedRuns::base_of(int layout) const {
  const auto L = static_cast<std::size_t>(layout);
  return select_rows(lattice_bases[static_cast<std::size_t>(lattice_of[L])], lattice_rows[L]);
}

void PreparedRuns::take_off_estimates(RunData& run, int layout, const SchemeEstimates& estimates) const {
  const auto L = static_cast<std::size_t>(layout);
  const Eigen::MatrixXd& on_lattice = lattice_bases[static_cast<std::size_t>(lattice_of[L])].estimate_map;
  const std::vector<Eigen::Index>& rows = lattice_rows[L];
  const auto n = static_cast<Eigen::Index>(run.values.size());  // the layout's first n rows
  INSMC_ASSERT(n <= static_cast<Eigen::Index>(rows.size()), "run of {} values on a layout of {} rows", n, rows.size());
  Eigen::MatrixXd map(n, on_lattice.cols());
  for (Eigen::Index i = 0; i < n; ++i) map.row(i) = on_lattice.row(rows[static_cast<std::size_t>(i)]);
  Eigen::Map<Eigen::VectorXd>(run.values.data(), n) -= map * estimates;
}

PreparedRuns prepare(const Records& records, const RecordReading& options) {
  PreparedRuns p;
  p.site = records.site;
  p.x_var = options.prior.variance();
  p.runs = extract_runs(records.file, p.site, options.extraction);
  std::vector<const Layout*> all;
  for (const RunData& run : p.runs) all.push_back(&run.layout);
  if (!all.empty()) p.add_lattice(all);
  // The layouts no other run extends come first (in file order); a run that
  // stops early is then analysed under the layout of a longer run it is the
  // beginning of: its cost is that run's, not a layout of its own.
  for (const RunData& run : p.runs) {
    const bool extended = std::any_of(p.runs.begin(), p.runs.end(), [&](const RunData& other) {
      return other.layout.rows.size() > run.layout.rows.size() && rows_begun(run.layout, other.layout) > 0;
    });
    if (!extended) p.layout_index(run.layout);
  }
  for (std::size_t r = 0; r < p.runs.size(); ++r) {
    const int L = p.place(p.runs[r]);
    p.layout_of.push_back(L);
    if (!records.estimates.empty())
      p.take_off_estimates(p.runs[r], L, records.estimates[r]);
  }
  return p;
}

void PreparedRuns::add_lattice(std::span<const Layout* const> of) {
  std::size_t largest = 0, apart = 0;
  for (std::size_t i = 0; i < of.size(); ++i) {
    const Layout* l = of[i];
    largest = std::max(largest, l->rows.size());
    if (l->nav != of.front()->nav || l->nav_start_s != of.front()->nav_start_s) return;
    // The rows the layouts would be fitted on apart: each distinct one once.
    if (std::none_of(of.begin(), of.begin() + static_cast<std::ptrdiff_t>(i), [&](const Layout* e) { return *e == *l; }))
      apart += l->rows.size();
  }
  Layout lattice = layout_union(of);
  const auto rows = static_cast<double>(lattice.rows.size());
  if (rows > kLatticeGrowth * static_cast<double>(largest) && rows > static_cast<double>(apart) / kLatticeGrowth) return;
  lattice_bases.push_back(make_base_model(lattice, site, x_var));
  lattices.push_back(std::move(lattice));
}

int PreparedRuns::layout_index(const Layout& layout) {
  for (std::size_t i = 0; i < layouts.size(); ++i)
    if (layouts[i] == layout) return static_cast<int>(i);
  std::optional<std::vector<Eigen::Index>> rows;
  std::size_t lattice = 0;
  for (; lattice < lattices.size() && !rows; ++lattice) rows = rows_within(layout, lattices[lattice]);
  if (rows) {
    --lattice;
  } else {
    // A layout of its own: its lattice is itself.
    lattices.push_back(layout);
    lattice_bases.push_back(make_base_model(layout, site, x_var));
    rows.emplace(layout.rows.size());
    for (std::size_t i = 0; i < rows->size(); ++i) (*rows)[i] = static_cast<Eigen::Index>(i);
  }
  layouts.push_back(layout);
  lattice_of.push_back(static_cast<int>(lattice));
  lattice_rows.push_back(std::move(*rows));
  keys.add_layout(layout);
  return static_cast<int>(layouts.size() - 1);
}

int PreparedRuns::place(RunData& run) {
  for (std::size_t i = 0; i < layouts.size(); ++i)
    if (layouts[i] == run.layout) return static_cast<int>(i);
  for (std::size_t i = 0; i < layouts.size(); ++i) {
    const std::size_t n = rows_begun(run.layout, layouts[i]);
    if (n == 0) continue;
    run.layout.rows.resize(n);
    run.values.resize(n);
    return static_cast<int>(i);
  }
  return layout_index(run.layout);
}

void for_each_layout_analyser(const PreparedRuns& p, const std::vector<std::vector<const Extension*>>& extensions,
                              const std::vector<bool>& used,
                              const std::function<void(std::size_t layout, RunAnalyser&& analyser)>& use) {
  INSMC_ASSERT(extensions.empty() || extensions.size() == p.lattices.size(), "extensions for {} lattices, {} expected",
               extensions.size(), p.lattices.size());
  for (std::size_t l = 0; l < p.lattices.size(); ++l) {
    std::optional<LatticeAnalysis> shared;
    for (std::size_t L = 0; L < p.layouts.size(); ++L) {
      if (static_cast<std::size_t>(p.lattice_of[L]) != l || (!used.empty() && !used[L])) continue;
      if (!shared) shared.emplace(p.lattices[l], combine(p.lattice_bases[l], extensions.empty() ? std::vector<const Extension*>{} : extensions[l]));
      use(L, RunAnalyser(p.layouts[L], *shared, p.lattice_rows[L]));
    }
  }
}

std::vector<std::optional<RunAnalyser>> layout_analysers(const PreparedRuns& p,
                                                         const std::vector<std::vector<const Extension*>>& extensions,
                                                         const std::vector<bool>& used) {
  std::vector<std::optional<RunAnalyser>> out(p.layouts.size());
  for_each_layout_analyser(p, extensions, used, [&](std::size_t L, RunAnalyser&& a) { out[L].emplace(std::move(a)); });
  return out;
}

Eigen::VectorXd run_values(const RunData& run) {
  return Eigen::Map<const Eigen::VectorXd>(run.values.data(), static_cast<Eigen::Index>(run.values.size()));
}

}  // namespace insmc::runs
