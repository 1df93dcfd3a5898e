#include "montecarlo/records/runs/model/gaussian_model.h"

#include "lib/common/assert.h"
#include "montecarlo/records/runs/model/response.h"
#include "montecarlo/records/runs/model/row_subset.h"
#include "montecarlo/records/runs/model/scheme_rows.h"

namespace insmc::runs {

BaseModel make_base_model(const Layout& layout, const RecordSite& site, const UncertaintyVector& x_var) {
  BaseModel base;
  base.H_x = uncertainty_response(layout, site);
  base.x_var = x_var;
  // After a scheme its r rows follow the scheme's maps.
  static const TestRunEstimators kNoEstimators;
  const SchemeRows scheme = scheme_rows(layout, site, site.estimators ? *site.estimators : kNoEstimators);
  for (std::size_t i = 0; i < layout.rows.size(); ++i)
    if (scheme.replaced[i]) base.H_x.row(static_cast<Eigen::Index>(i)) = scheme.x_columns.row(static_cast<Eigen::Index>(i));
  base.scheme_columns = scheme.columns;
  base.scheme_x_index = scheme.x_index;
  base.scheme_variance = scheme.variance;
  base.estimate_map = scheme.estimate_map;
  const double q = site.position_resolution_m;
  const auto n = static_cast<Eigen::Index>(layout.rows.size());
  base.prior_std = (base.H_x.array().square().rowwise() * base.x_var.transpose().array()).rowwise().sum().sqrt();
  base.actual_noise_var.resize(n);
  base.noise_var.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const bool f = layout.rows[static_cast<std::size_t>(i)].quantity == Quantity::kF;
    base.actual_noise_var[i] = f ? 0.0 : q * q / 12.0;
    // The model-error floor: on r rows an absolute part and a share of the
    // row's spread under these priors (second-order terms grow with the
    // uncertainties; --bound widens it, and the null is calibrated on it).
    // A candidate's extension keeps it (combine()).
    const double floor = f ? kFNoiseFloorMps2 : kAbsoluteModelErrorM + kRelativeModelError * base.prior_std[i];
    base.noise_var[i] = base.actual_noise_var[i] + floor * floor;
  }
  base.counting = pulse_counting(layout, site, site.dv_pulse_mps, x_var, base.noise_var.cwiseSqrt());
  return base;
}

GaussianModel combine(const BaseModel& base, const std::vector<const Extension*>& extensions) {
  UncertaintyVector x_var = base.x_var;
  const PulseCounting* counting = &base.counting;
  Eigen::Index extra = 0;
  for (const Extension* e : extensions) {
    x_var = x_var.cwiseProduct(e->x_var_scale) + e->x_var_add;
    extra += e->columns.cols();
    if (e->counting) counting = &*e->counting;
  }
  const Eigen::Index n = base.H_x.rows(), kc = counting->columns.cols(), ks = base.scheme_columns.cols();
  GaussianModel m;
  m.H.resize(n, uncertainty_slot::kDim + kc + ks + extra);
  m.prior_var.resize(uncertainty_slot::kDim + kc + ks + extra);
  m.H.leftCols(uncertainty_slot::kDim) = base.H_x;
  m.prior_var.head(uncertainty_slot::kDim) = x_var;
  m.H.middleCols(uncertainty_slot::kDim, kc) = counting->columns;
  m.prior_var.segment(uncertainty_slot::kDim, kc).setOnes();
  m.H.middleCols(uncertainty_slot::kDim + kc, ks) = base.scheme_columns;
  for (Eigen::Index j = 0; j < ks; ++j) {
    const int slot = base.scheme_x_index[static_cast<std::size_t>(j)];
    m.prior_var[uncertainty_slot::kDim + kc + j] = slot >= 0 ? x_var[slot] : base.scheme_variance[j];
  }
  // The floor stays the base model's when a candidate widens the priors: the
  // null calibrates its share (κ, λ) for that floor, and a floor grown with
  // the candidate's priors would weight down the very r rows where the
  // candidate's signature lies (docs/gap-method.md §1).
  m.noise_var = base.noise_var + counting->noise_var;
  m.actual_noise_var = base.actual_noise_var + counting->noise_var;
  m.mean = Eigen::VectorXd::Zero(n);
  Eigen::Index at = uncertainty_slot::kDim + kc + ks;
  for (const Extension* e : extensions) {
    INSMC_ASSERT(e->columns.rows() == n || e->columns.cols() == 0, "extension rows {}", e->columns.rows());
    const Eigen::Index k = e->columns.cols();
    if (k > 0) {
      m.H.middleCols(at, k) = e->columns;
      m.prior_var.segment(at, k) = e->column_var;
    }
    at += k;
    if (e->noise_var_add.size() == n) {
      m.noise_var += e->noise_var_add;
      m.actual_noise_var += e->noise_var_add;
    }
    if (e->mean.size() == n) m.mean += e->mean;
  }
  return m;
}

namespace {

PulseCounting counting_rows_of(const PulseCounting& c, std::span<const Eigen::Index> rows) {
  return {rows_of(c.columns, rows), rows_of(c.noise_var, rows)};
}

}  // namespace

BaseModel select_rows(const BaseModel& base, std::span<const Eigen::Index> rows) {
  BaseModel out = base;
  out.H_x = rows_of(base.H_x, rows);
  out.noise_var = rows_of(base.noise_var, rows);
  out.actual_noise_var = rows_of(base.actual_noise_var, rows);
  out.prior_std = rows_of(base.prior_std, rows);
  out.counting = counting_rows_of(base.counting, rows);
  out.scheme_columns = rows_of(base.scheme_columns, rows);
  out.estimate_map = rows_of(base.estimate_map, rows);
  return out;
}

Extension select_rows(const Extension& e, std::span<const Eigen::Index> rows) {
  Extension out = e;
  if (e.columns.cols() > 0) out.columns = rows_of(e.columns, rows);
  else out.columns.resize(static_cast<Eigen::Index>(rows.size()), 0);
  out.noise_var_add = rows_of(e.noise_var_add, rows);
  out.mean = rows_of(e.mean, rows);
  if (e.counting) out.counting = counting_rows_of(*e.counting, rows);
  return out;
}

GaussianModel select_rows(const GaussianModel& model, std::span<const Eigen::Index> rows) {
  GaussianModel out;
  out.mean = rows_of(model.mean, rows);
  out.H = rows_of(model.H, rows);
  out.prior_var = model.prior_var;
  out.noise_var = rows_of(model.noise_var, rows);
  out.actual_noise_var = rows_of(model.actual_noise_var, rows);
  return out;
}

GaussianModel first_rows(GaussianModel model, Eigen::Index rows) {
  if (rows == model.H.rows()) return model;
  if (model.mean.size() > 0) model.mean.conservativeResize(rows);
  model.H.conservativeResize(rows, Eigen::NoChange);
  model.noise_var.conservativeResize(rows);
  model.actual_noise_var.conservativeResize(rows);
  return model;
}

}  // namespace insmc::runs
