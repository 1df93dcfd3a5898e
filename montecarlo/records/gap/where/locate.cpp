#include "montecarlo/records/gap/where/locate.h"

#include "montecarlo/records/gap/where/where.h"

namespace insmc::gap {

GapLocation locate_gap(const runs::PreparedRuns& p, const std::vector<std::optional<runs::RunAnalyser>>& analysers,
                       const Pooled& observed, const ModelNull& null, const std::vector<Eigen::VectorXd>& null_z,
                       const std::vector<int>& null_layout, double alpha, bool pessimistic_significant,
                       const OwnNoiseRuns* own_noise) {
  GapLocation d;
  d.groups = group_results(observed, null.calibration, null.log_ratios, alpha);
  if (own_noise) add_own_noise_bands(d.groups, own_noise->log_ratios, alpha);
  if (pessimistic_significant) d.pessimistic_where = pessimistic_groups(d.groups, null.log_ratios, alpha);
  d.by_kind = shares_by(d.groups, [](const GroupResult& g) {
    return std::string(g.coherent ? "common to all runs" : "run-to-run scatter");
  });
  d.by_axis = shares_by(d.groups, [](const GroupResult& g) {
    const int axis = runs::group_axis(g.representative());
    return axis < 0 ? std::string("estimates") : std::string(1, "xyz"[axis]);
  });
  d.by_stage = shares_by(d.groups, [](const GroupResult& g) { return runs::group_stage(g.representative()); });
  d.by_window = shares_by(d.groups, [](const GroupResult& g) {
    if (g.representative() == runs::kEstimatesGroup) return std::string("estimates");
    return g.coherent && runs::group_stage(g.representative()) != "test-run fit" ? std::string("after test (all windows)")
                                                                               : runs::group_window(g.group);
  });
  std::vector<Eigen::VectorXd> z(p.runs.size());
  std::vector<const runs::Layout*> layouts, null_layouts;
  std::vector<const Eigen::VectorXd*> expected, null_expected;
  for (std::size_t r = 0; r < p.runs.size(); ++r) {
    const runs::RunAnalyser& a = *analysers[static_cast<std::size_t>(p.layout_of[r])];
    a.analyse(run_values(p.runs[r]), z[r]);
    layouts.push_back(&p.layouts[static_cast<std::size_t>(p.layout_of[r])]);
    expected.push_back(&a.expected_square());
  }
  for (std::size_t j = 0; j < null_z.size(); ++j) {
    null_layouts.push_back(&p.layouts[static_cast<std::size_t>(null_layout[j])]);
    null_expected.push_back(&analysers[static_cast<std::size_t>(null_layout[j])]->expected_square());
  }
  d.time_functions = time_function_shares(layouts, z, p.site);
  d.allan = allan_curves(layouts, z, expected, null_layouts, null_z, null_expected, p.site.filter_interval_s);
  if (!own_noise) return d;
  std::vector<const runs::Layout*> own_layouts;
  std::vector<const Eigen::VectorXd*> own_expected;
  for (const int l : own_noise->layout_of) {
    // A null run placed in a layout the base analysers predate has no
    // expectation here: no own-noise Allan band rather than a guess.
    const auto k = static_cast<std::size_t>(l);
    if (k >= analysers.size() || !analysers[k]) return d;
    own_layouts.push_back(&p.layouts[k]);
    own_expected.push_back(&analysers[k]->expected_square());
  }
  const std::vector<AllanCurve> own =
      allan_curves(layouts, z, expected, own_layouts, own_noise->z, own_expected, p.site.filter_interval_s);
  for (std::size_t axis = 0; axis < d.allan.size() && axis < own.size(); ++axis)
    for (AllanPoint& point : d.allan[axis].points)
      for (const AllanPoint& o : own[axis].points)
        if (o.cluster_s == point.cluster_s) {
          point.own_noise = o.null;
          point.own_noise_low = o.null_low;
          point.own_noise_high = o.null_high;
        }
  return d;
}

}  // namespace insmc::gap
