#include "montecarlo/records/gap/candidates/common.h"

#include <algorithm>

#include <cmath>
#include <utility>

namespace insmc::gap::candidates {

std::vector<double> scaled(std::initializer_list<double> values, double unit) {
  std::vector<double> out;
  for (double v : values) out.push_back(v * unit);
  return out;
}

std::vector<double> log_grid(double lo, double hi, double unit) {
  std::vector<double> out;
  for (int k = 0;; ++k) {
    const double v = lo * std::pow(10.0, k / 4.0);
    if (v > hi * 1.01) break;
    out.push_back(v * unit);
  }
  return out;
}

CandidateParameter searched(std::string name, Dimension dimension, std::vector<double> grid, double lower_si,
                            double upper_si, std::string why) {
  return {std::move(name), dimension, std::move(grid), false, lower_si, upper_si, std::move(why)};
}

CandidateParameter amplitude(std::string name, Dimension dimension, double largest_si, std::string why) {
  return {std::move(name), dimension, {largest_si}, true, -largest_si, largest_si, std::move(why)};
}

double layout_end(const runs::Layout& layout) {
  double end = 0.0;
  for (const runs::ObservationRow& r : layout.rows) end = std::max(end, r.t_s);
  return end;
}

Eigen::VectorXd f_noise(const LayoutContext& ctx, const Eigen::Vector3d& var) {
  Eigen::VectorXd add = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(ctx.layout->rows.size()));
  for (std::size_t i = 0; i < ctx.layout->rows.size(); ++i) {
    const runs::ObservationRow& r = ctx.layout->rows[i];
    if (r.quantity == runs::Quantity::kF) add[static_cast<Eigen::Index>(i)] = var[r.axis];
  }
  return add;
}

Eigen::VectorXd tilt_f_noise(const LayoutContext& ctx, double angle_var_rad2, double growth_rad2ps) {
  Eigen::VectorXd add = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(ctx.layout->rows.size()));
  for (std::size_t i = 0; i < ctx.layout->rows.size(); ++i) {
    const runs::ObservationRow& r = ctx.layout->rows[i];
    if (r.quantity != runs::Quantity::kF) continue;
    // δf = δθ × f: with the same variance about every axis, axis k sees the
    // other two components of f.
    const Eigen::Vector3d f = specific_force(r.t_s, ctx.site->model);
    const double var = angle_var_rad2 + growth_rad2ps * std::max(r.t_s, 0.0);
    add[static_cast<Eigen::Index>(i)] = var * (f.squaredNorm() - f[r.axis] * f[r.axis]);
  }
  return add;
}

Eigen::MatrixXd signature_columns(const LayoutContext& ctx, const std::string& key, int columns,
                                  const std::function<void(double, runs::Columns3&, runs::Columns3&)>& at) {
  if (auto it = ctx.cache.find(key); it != ctx.cache.end()) return it->second;
  runs::InputSignal in;
  in.columns = columns;
  in.at = at;
  Eigen::MatrixXd r = input_response(*ctx.layout, *ctx.site, in);
  ctx.cache[key] = r;
  return r;
}

Eigen::Vector3d specific_force(double t, const ModelOptions& m) { return -runs::gravity_in_ap(t, m); }

}  // namespace insmc::gap::candidates
