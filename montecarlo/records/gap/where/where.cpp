#include "montecarlo/records/gap/where/where.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

namespace insmc::gap {
namespace {

/// The null files' ℓ of a group, its α/2 and 1 − α/2 quantiles (the band
/// the groups plot draws); none when no null file has the group.
template <class Pick>
std::optional<std::pair<double, double>> group_band(const std::vector<LogRatios>& null_log_ratios, const Pick& pick,
                                                    double alpha) {
  std::vector<double> v;
  for (const LogRatios& nl : null_log_ratios)
    if (const double x = pick(nl); std::isfinite(x)) v.push_back(x);
  if (v.empty()) return std::nullopt;
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) { return v[static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)))]; };
  return std::pair{at(0.5 * alpha), at(1 - 0.5 * alpha)};
}

}  // namespace

void add_own_noise_bands(std::vector<GroupResult>& groups, const std::vector<LogRatios>& own_noise_log_ratios,
                         double alpha) {
  for (GroupResult& r : groups) {
    const auto k = static_cast<std::size_t>(r.group);
    const auto b = r.coherent ? group_band(own_noise_log_ratios, [k](const LogRatios& nl) { return nl.coherent[k]; }, alpha)
                              : group_band(own_noise_log_ratios, [k](const LogRatios& nl) { return nl.scatter[k]; }, alpha);
    if (b) std::tie(r.own_noise_low, r.own_noise_high) = *b;
  }
}

std::vector<GroupResult> group_results(const Pooled& observed, const NullCalibration& calibration,
                                       const std::vector<LogRatios>& null_log_ratios, double alpha) {
  const LogRatios l = log_ratios(observed, calibration, CoherentReference::kAtLeastModelScatter);
  const GroupValues power = group_power(observed.power);
  const GroupValues null_power = expected_power(observed.power, calibration);
  const CoherentValues coherent = coherent_power(observed);
  const CoherentValues null_coherent =
      expected_coherent_power(observed, calibration, CoherentReference::kAtLeastModelScatter);
  double total = 0;
  for (double v : l.scatter)
    if (std::isfinite(v)) total += v * v;
  for (double v : l.coherent)
    if (std::isfinite(v)) total += v * v;
  const auto p_value = [&](const auto& pick, double value) {
    std::size_t above = 0;
    for (const LogRatios& nl : null_log_ratios) {
      const double v = pick(nl);
      if (!std::isfinite(v) || std::abs(v) >= std::abs(value)) ++above;
    }
    return (1.0 + static_cast<double>(above)) / (1.0 + static_cast<double>(null_log_ratios.size()));
  };
  const auto band = [&](const auto& pick, GroupResult& r) {
    if (const auto b = group_band(null_log_ratios, pick, alpha)) std::tie(r.null_low, r.null_high) = *b;
  };
  std::vector<GroupResult> out;
  for (int g = 0; g < runs::kGroupCount; ++g) {
    if (!std::isfinite(l.scatter[g])) continue;
    out.push_back({false, g, observed.power.count[g], power[g], null_power[g], l.scatter[g],
                   p_value([g](const LogRatios& nl) { return nl.scatter[g]; }, l.scatter[g]),
                   total > 0 ? l.scatter[g] * l.scatter[g] / total : 0.0, 0.0, 0.0});
    band([g](const LogRatios& nl) { return nl.scatter[g]; }, out.back());
  }
  for (int c = 0; c < runs::kCoherentCount; ++c) {
    const auto k = static_cast<std::size_t>(c);
    if (!std::isfinite(l.coherent[k])) continue;
    double count = 0;
    for (int g = 0; g < runs::kGroupCount; ++g)
      if (runs::coherent_group_of(g) == c) count += observed.power.count[g];
    out.push_back({true, c, count, coherent[k], null_coherent[k], l.coherent[k],
                   p_value([k](const LogRatios& nl) { return nl.coherent[k]; }, l.coherent[k]),
                   total > 0 ? l.coherent[k] * l.coherent[k] / total : 0.0, 0.0, 0.0});
    band([k](const LogRatios& nl) { return nl.coherent[k]; }, out.back());
  }
  return out;
}

std::vector<std::string> pessimistic_groups(const std::vector<GroupResult>& groups,
                                            const std::vector<LogRatios>& null_log_ratios, double alpha) {
  std::vector<const GroupResult*> below, beyond;
  for (const GroupResult& g : groups)
    if (g.log_ratio < 0) below.push_back(&g);
  std::sort(below.begin(), below.end(), [](const GroupResult* a, const GroupResult* b) { return a->log_ratio < b->log_ratio; });
  for (const GroupResult* g : below) {
    std::size_t as_low = 0;
    for (const LogRatios& nl : null_log_ratios) {
      const double v = g->coherent ? nl.coherent[static_cast<std::size_t>(g->group)] : nl.scatter[static_cast<std::size_t>(g->group)];
      if (!std::isfinite(v) || v <= g->log_ratio) ++as_low;
    }
    if ((1.0 + static_cast<double>(as_low)) / (1.0 + static_cast<double>(null_log_ratios.size())) < alpha) beyond.push_back(g);
  }
  if (beyond.empty() && !below.empty()) beyond.push_back(below.front());
  std::vector<std::string> out;
  for (const GroupResult* g : beyond) out.push_back(g->name());
  return out;
}

std::vector<Share> shares_by(const std::vector<GroupResult>& groups,
                             const std::function<std::string(const GroupResult&)>& key) {
  std::vector<Share> out;
  for (const GroupResult& g : groups) {
    const std::string k = key(g);
    auto it = std::find_if(out.begin(), out.end(), [&](const Share& s) { return s.name == k; });
    if (it == out.end()) out.push_back({k, g.share});
    else it->share += g.share;
  }
  return out;
}

std::vector<TimeFunctionShares> time_function_shares(const std::vector<const runs::Layout*>& layouts,
                                                     const std::vector<Eigen::VectorXd>& z,
                                                     const runs::RecordSite& site) {
  const char* names[] = {"Schuler sin/cos(w_s t)", "earth rate sin/cos(w_ie t)", "t^2", "t^3", "t^4", "rest"};
  const double ws = site.model.schuler_radps(), wie = site.model.earth_rate_radps;
  std::vector<TimeFunctionShares> out;
  for (int axis = 0; axis < 3; ++axis) {
    double explained[5] = {}, total = 0;
    for (std::size_t r = 0; r < layouts.size(); ++r) {
      std::vector<double> t, v;
      // z[r] holds the run's rows: all of the layout's, or its first ones.
      for (std::size_t i = 0; i < static_cast<std::size_t>(z[r].size()); ++i) {
        const runs::ObservationRow& row = layouts[r]->rows[i];
        if (static_cast<int>(i) < layouts[r]->test_rows || row.quantity != runs::Quantity::kR || row.axis != axis) continue;
        t.push_back(row.t_s);
        v.push_back(z[r][static_cast<Eigen::Index>(i)]);
      }
      const auto m = static_cast<Eigen::Index>(t.size());
      if (m < 8) continue;
      const double end = t.back();
      Eigen::VectorXd rest = Eigen::Map<Eigen::VectorXd>(v.data(), m);
      total += rest.squaredNorm();
      for (int f = 0; f < 5; ++f) {
        Eigen::MatrixXd basis(m, f < 2 ? 2 : 1);
        for (Eigen::Index i = 0; i < m; ++i) {
          const double ti = t[static_cast<std::size_t>(i)];
          if (f == 0) basis(i, 0) = std::sin(ws * ti), basis(i, 1) = std::cos(ws * ti);
          else if (f == 1) basis(i, 0) = std::sin(wie * ti), basis(i, 1) = std::cos(wie * ti);
          else basis(i, 0) = std::pow(ti / end, f);
        }
        const Eigen::VectorXd fit = basis * basis.colPivHouseholderQr().solve(rest);
        explained[f] += fit.squaredNorm();
        rest -= fit;
      }
    }
    TimeFunctionShares s{axis, {}};
    if (total > 0) {
      double used = 0;
      for (int f = 0; f < 5; ++f) s.shares.push_back({names[f], explained[f] / total}), used += explained[f] / total;
      s.shares.push_back({names[5], std::max(0.0, 1.0 - used)});
    }
    out.push_back(s);
  }
  return out;
}

namespace {

/// Σ of squared differences of consecutive cluster means and their count,
/// per cluster size, for one axis of one run's f residuals.
void add_allan(const runs::Layout& layout, const Eigen::VectorXd& z, const Eigen::VectorXd& expected, int axis,
               std::map<int, std::pair<double, double>>& acc) {
  std::vector<double> e;
  for (std::size_t i = 0; i < static_cast<std::size_t>(z.size()); ++i)  // the run's rows: a prefix of the layout
    if (layout.rows[i].quantity == runs::Quantity::kF && layout.rows[i].axis == axis)
      e.push_back(z[static_cast<Eigen::Index>(i)] * std::sqrt(expected[static_cast<Eigen::Index>(i)]));
  for (int m = 1; 4 * m <= static_cast<int>(e.size()); m *= 2) {
    std::vector<double> means;
    for (std::size_t s = 0; s + static_cast<std::size_t>(m) <= e.size(); s += static_cast<std::size_t>(m)) {
      double sum = 0;
      for (int k = 0; k < m; ++k) sum += e[s + static_cast<std::size_t>(k)];
      means.push_back(sum / m);
    }
    for (std::size_t k = 1; k < means.size(); ++k) {
      acc[m].first += (means[k] - means[k - 1]) * (means[k] - means[k - 1]);
      acc[m].second += 1;
    }
  }
}

}  // namespace

std::vector<AllanCurve> allan_curves(const std::vector<const runs::Layout*>& layouts,
                                     const std::vector<Eigen::VectorXd>& z,
                                     const std::vector<const Eigen::VectorXd*>& expected,
                                     const std::vector<const runs::Layout*>& null_layouts,
                                     const std::vector<Eigen::VectorXd>& null_z,
                                     const std::vector<const Eigen::VectorXd*>& null_expected,
                                     double filter_interval_s) {
  // The null band: the same curve of null files as large as the records
  // (consecutive null runs), 5–95 % over those files.
  const std::size_t per_file = std::max<std::size_t>(layouts.size(), 1);
  const std::size_t files = null_layouts.size() / per_file;
  std::vector<AllanCurve> out;
  for (int axis = 0; axis < 3; ++axis) {
    std::map<int, std::pair<double, double>> data, null;
    std::vector<std::map<int, std::pair<double, double>>> by_file(files);
    for (std::size_t r = 0; r < layouts.size(); ++r) add_allan(*layouts[r], z[r], *expected[r], axis, data);
    for (std::size_t r = 0; r < null_layouts.size(); ++r) {
      add_allan(*null_layouts[r], null_z[r], *null_expected[r], axis, null);
      if (r / per_file < files) add_allan(*null_layouts[r], null_z[r], *null_expected[r], axis, by_file[r / per_file]);
    }
    AllanCurve c{axis, {}};
    for (const auto& [m, sum] : data) {
      if (sum.second <= 0 || !null.count(m) || null[m].second <= 0) continue;
      // Allan variance ½ ⟨(ȳ_{k+1} − ȳ_k)²⟩.
      AllanPoint point{m * filter_interval_s, std::sqrt(0.5 * sum.first / sum.second),
                       std::sqrt(0.5 * null[m].first / null[m].second), 0.0, 0.0};
      std::vector<double> band;
      for (const auto& f : by_file)
        if (const auto it = f.find(m); it != f.end() && it->second.second > 0)
          band.push_back(std::sqrt(0.5 * it->second.first / it->second.second));
      std::sort(band.begin(), band.end());
      point.null_low = band.empty() ? point.null : band[static_cast<std::size_t>(0.05 * static_cast<double>(band.size() - 1))];
      point.null_high = band.empty() ? point.null
                                     : band[static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(band.size() - 1)))];
      c.points.push_back(point);
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace insmc::gap
