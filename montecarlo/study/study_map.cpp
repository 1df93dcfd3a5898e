#include "montecarlo/study/study_map.h"

#include <cmath>

#include "lib/propagation/position_maps.h"

namespace insmc::mc {
namespace {

constexpr int kRowsPerMap = 5;  // x, y, z, north, east

struct Moments {
  double m, v;  // mean and variance of a linear output
};

}  // namespace

StudyMap::StudyMap(const StudyConfig& c, const StudyLayout& l) : config_(&c), layout_(&l) {
  const int n_maps = static_cast<int>(c.schemes.size()) * l.n_systems * l.n_times;
  map_t_.resize(ux::kDim, kRowsPerMap * n_maps);
  int m = 0;
  for (size_t i = 0; i < c.schemes.size(); ++i) {
    for (System s : c.systems) {
      const std::vector<Sensitivity3> maps = position_maps(s, c.fidelity, c.model, l.times_s);
      for (int k = 0; k < l.n_times; ++k, ++m) {
        const Eigen::Matrix<double, 2, ux::kDim> ne = local_level_horizontal(l.times_s[k], c.model) * maps[k];
        map_t_.block<ux::kDim, 3>(0, kRowsPerMap * m) = maps[k].transpose();
        map_t_.block<ux::kDim, 2>(0, kRowsPerMap * m + 3) = ne.transpose();
      }
    }
  }
  // Exact moments: r = Σ s_j x_j with independent, symmetric x_j.
  const UncertaintyVector mu = c.uncertainties.mean(), v = c.uncertainties.variance();
  const UncertaintyVector k4 = c.uncertainties.fourth_central_moment() - v.cwiseProduct(v) * 3.0;
  auto moments = [&](int row) {
    const auto s = map_t_.col(row);
    return Moments{s.dot(mu), s.cwiseProduct(s).dot(v)};
  };
  // Var(r²) = 4m²V + 2V² + Σ s⁴(m4 − 3v²) for one row.
  auto var_sq = [&](int row, const Moments& mo) {
    const auto s = map_t_.col(row);
    const double excess = s.cwiseProduct(s).cwiseProduct(s.cwiseProduct(s)).dot(k4);
    return 4 * mo.m * mo.m * mo.v + 2 * mo.v * mo.v + excess;
  };
  for (const OutputSpec& o : l.outputs) {
    const int map_index = static_cast<int>(&o - l.outputs.data()) / 4;
    const int base = kRowsPerMap * map_index;
    if (o.axis != Axis::kHorizontal) {
      const int row = base + static_cast<int>(o.axis);
      const Moments mo = moments(row);
      mean_.push_back(mo.m);
      rms_.push_back(std::sqrt(mo.m * mo.m + mo.v));
      var_r2_.push_back(var_sq(row, mo));
    } else {
      const Moments n = moments(base + 3), e = moments(base + 4);
      const auto a = map_t_.col(base + 3), b = map_t_.col(base + 4);
      const double cov = a.cwiseProduct(b).dot(v);
      const double cov_sq = 4 * n.m * e.m * cov + 2 * cov * cov +
                            a.cwiseProduct(a).cwiseProduct(b.cwiseProduct(b)).dot(k4);
      mean_.push_back(std::hypot(n.m, e.m));  // the value when the spread is zero
      rms_.push_back(std::sqrt(n.m * n.m + e.m * e.m + n.v + e.v));
      var_r2_.push_back(var_sq(base + 3, n) + var_sq(base + 4, e) + 2 * cov_sq);
    }
  }
}

double StudyMap::output_value(const double* r, Axis axis) {
  return axis == Axis::kHorizontal ? std::hypot(r[3], r[4]) : r[static_cast<int>(axis)];
}

std::vector<std::vector<double>> StudyMap::variance_shares() const {
  const UncertaintyVector v = config_->uncertainties.variance();
  std::vector<std::vector<double>> out;
  for (size_t o = 0; o < layout_->outputs.size(); ++o) {
    const int base = kRowsPerMap * static_cast<int>(o / 4);
    const Axis axis = layout_->outputs[o].axis;
    Eigen::Matrix<double, ux::kDim, 1> contrib;
    if (axis == Axis::kHorizontal) {
      contrib = (map_t_.col(base + 3).cwiseAbs2() + map_t_.col(base + 4).cwiseAbs2()).cwiseProduct(v);
    } else {
      contrib = map_t_.col(base + static_cast<int>(axis)).cwiseAbs2().cwiseProduct(v);
    }
    const double total = rms_[o] * rms_[o];
    std::vector<double> shares(ux::kDim, 0.0);
    if (total > 0)
      for (int j = 0; j < ux::kDim; ++j) shares[j] = contrib[j] / total;
    out.push_back(std::move(shares));
  }
  return out;
}

std::vector<double> StudyMap::mean_shares() const {
  std::vector<double> out;
  for (size_t o = 0; o < mean_.size(); ++o) {
    const double total = rms_[o] * rms_[o];
    out.push_back(total > 0 ? mean_[o] * mean_[o] / total : 0.0);
  }
  return out;
}

}  // namespace insmc::mc
