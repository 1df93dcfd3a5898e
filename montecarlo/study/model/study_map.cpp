#include "montecarlo/study/model/study_map.h"

#include <cmath>

#include "lib/compensation/compensation_maps.h"
#include "lib/propagation/position_maps.h"
#include "lib/uncertainty/catalogue.h"

namespace insmc::mc {
namespace {

struct Moments {
  double m, v;
};

}  // namespace

int StudyMap::system_index(std::size_t o) const {
  return static_cast<int>((o / 4 / static_cast<std::size_t>(layout_->n_times)) % static_cast<std::size_t>(layout_->n_systems));
}

int StudyMap::row_base(std::size_t o) const {
  const std::size_t map_index = o / 4;  // (scheme, system, time)
  const std::size_t nt = static_cast<std::size_t>(layout_->n_times), ns = static_cast<std::size_t>(layout_->n_systems);
  const std::size_t k = map_index % nt, scheme_i = map_index / nt / ns;
  return kRowsPerMap * static_cast<int>(scheme_i * nt + k);
}

StudyMap::StudyMap(const StudyConfig& c, const StudyLayout& l) : config_(&c), layout_(&l) {
  const int n_schemes = static_cast<int>(c.schemes.size());
  for (System s : c.systems) pipelines_.push_back(std::make_shared<const SystemPipeline>(c, s));
  for (int i = 0; i < n_schemes; ++i) {
    const SchemeMaps probe = scheme_position_maps(c.schemes[i], c.systems[0], c.map_fidelity(), c.model, c.test, {0.0});
    ready_time_s_.push_back(probe.ready_time_s);
  }
  for (int j = 0; j < l.n_systems; ++j) {
    Eigen::MatrixXd mt(z_slot::kDim, kRowsPerMap * n_schemes * l.n_times);
    for (int i = 0; i < n_schemes; ++i) {
      const SchemeMaps maps = scheme_position_maps(c.schemes[i], c.systems[j], c.map_fidelity(), c.model, c.test, l.times_s);
      for (int k = 0; k < l.n_times; ++k) {
        const int base = kRowsPerMap * (i * l.n_times + k);
        const Eigen::Matrix<double, 2, 3> h = local_level_horizontal(maps.frame_time_offset_s + l.times_s[k], c.model);
        mt.middleCols<3>(base) = maps.position[k].transpose();
        mt.middleCols<2>(base + 3) = (h * maps.position[k]).transpose();
      }
    }
    input_map_t_.push_back(pipelines_[j]->covariance_map().transpose() * mt);
    x_only_.push_back(mt.bottomRows(z_slot::kDim - uncertainty_slot::kDim).cwiseAbs().maxCoeff() == 0.0);
    map_t_.push_back(std::move(mt));
  }
  // Exact moments of r = s·w + s·E[w] with independent, symmetric inputs w.
  for (std::size_t o = 0; o < l.outputs.size(); ++o) {
    const int j = system_index(o), base = row_base(o);
    const SystemPipeline& p = *pipelines_[j];
    const Eigen::VectorXd& mu = p.input_mean();
    const Eigen::VectorXd& v = p.input_variance();
    const Eigen::VectorXd k4 = p.input_fourth_moment() - 3.0 * v.cwiseProduct(v);
    const Eigen::MatrixXd& s = input_map_t_[j];
    auto moments = [&](int row) { return Moments{s.col(row).dot(mu), s.col(row).cwiseAbs2().dot(v)}; };
    auto var_sq = [&](int row, const Moments& mo) {
      return 4 * mo.m * mo.m * mo.v + 2 * mo.v * mo.v + s.col(row).cwiseAbs2().cwiseAbs2().dot(k4);
    };
    const Axis axis = l.outputs[o].axis;
    if (axis != Axis::kHorizontal) {
      const int row = base + static_cast<int>(axis);
      const Moments mo = moments(row);
      mean_.push_back(mo.m);
      rms_.push_back(std::sqrt(mo.m * mo.m + mo.v));
      var_r2_.push_back(var_sq(row, mo));
      horizontal_.emplace_back();
    } else {
      const Moments n = moments(base + 3), e = moments(base + 4);
      const auto a = s.col(base + 3), b = s.col(base + 4);
      const double cov = a.cwiseProduct(b).dot(v);
      const double cov_sq = 4 * n.m * e.m * cov + 2 * cov * cov + a.cwiseAbs2().cwiseProduct(b.cwiseAbs2()).dot(k4);
      mean_.push_back(std::hypot(n.m, e.m));  // the value when the spread is zero
      rms_.push_back(std::sqrt(n.m * n.m + e.m * e.m + n.v + e.v));
      var_r2_.push_back(var_sq(base + 3, n) + var_sq(base + 4, e) + 2 * cov_sq);
      HorizontalMoments h;
      h.mean = {n.m, e.m};
      h.covariance << n.v, cov, cov, e.v;
      horizontal_.push_back(h);
    }
  }
}

double StudyMap::output_value(const double* r, Axis axis) {
  // sqrt(N² + E²), the engine's own formula, so --replay prints what the engine aggregates.
  return axis == Axis::kHorizontal ? std::sqrt(r[3] * r[3] + r[4] * r[4]) : r[static_cast<int>(axis)];
}

std::vector<std::string> StudyMap::budget_sources() const {
  std::vector<std::string> names;
  for (const auto& spec : catalogue()) names.emplace_back(spec.name);
  for (const RealignedSlot& r : kRealignedSlots) names.push_back("realignment:" + std::string(catalogue()[r.x_index].name));
  for (const char* n : {"position_resolution", "dv_pulses", "sway", "torquer_pulses", "alignment_dv_pulses", "mean"})
    names.emplace_back(n);
  return names;
}

std::vector<std::vector<double>> StudyMap::budget_shares() const {
  const int n1 = config_->test.intervals() + 1;
  const int kr = uncertainty_slot::kDim, nr = static_cast<int>(std::size(kRealignedSlots));
  // Input groups after x and the fresh draws (system_pipeline.cpp layout).
  const int groups[5][2] = {{kr + nr, 3 * n1},
                            {kr + nr + 3 * n1, 3 * n1},
                            {kr + nr + 6 * n1, 3 * n1},
                            {kr + nr + 9 * n1, 6},
                            {kr + nr + 9 * n1 + 6, 6}};
  std::vector<std::vector<double>> out;
  for (std::size_t o = 0; o < layout_->outputs.size(); ++o) {
    const int j = system_index(o), base = row_base(o);
    const Eigen::VectorXd& v = pipelines_[j]->input_variance();
    const Eigen::MatrixXd& s = input_map_t_[j];
    Eigen::VectorXd contrib = layout_->outputs[o].axis == Axis::kHorizontal
                                  ? (s.col(base + 3).cwiseAbs2() + s.col(base + 4).cwiseAbs2()).cwiseProduct(v).eval()
                                  : s.col(base + static_cast<int>(layout_->outputs[o].axis)).cwiseAbs2().cwiseProduct(v).eval();
    const double total = rms_[o] * rms_[o];
    std::vector<double> shares;
    for (int i = 0; i < kr + nr; ++i) shares.push_back(contrib[i]);
    for (const auto& g : groups) shares.push_back(contrib.segment(g[0], g[1]).sum());
    shares.push_back(mean_[o] * mean_[o]);
    for (double& x : shares) x = total > 0 ? x / total : 0.0;
    out.push_back(std::move(shares));
  }
  return out;
}

}  // namespace insmc::mc
