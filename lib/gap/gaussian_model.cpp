#include "lib/gap/gaussian_model.h"

#include "lib/common/assert.h"
#include "lib/gap/response.h"

namespace insmc::gap {

BaseModel make_base_model(const Layout& layout, const RecordSite& site, const UncertaintyVector& x_var) {
  BaseModel base;
  base.H_x = uncertainty_response(layout, site);
  base.x_var = x_var;
  const double w = site.dv_pulse_mps, tau = site.filter_interval_s, q = site.position_resolution_m;
  // The pulse phase ρ0 ~ U(−½, ½) pulses is an initial velocity error ρ0 w (simulator.h).
  base.x_var.segment<3>(ux::kInitialVelocity).array() += w * w / 12.0;
  const auto n = static_cast<Eigen::Index>(layout.rows.size());
  base.prior_std = (base.H_x.array().square().rowwise() * base.x_var.transpose().array()).rowwise().sum().sqrt();
  base.noise_var.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (layout.rows[static_cast<std::size_t>(i)].quantity == Quantity::kF) {
      // Δf over τ from pulses: (ρ_start − ρ_end) w/τ, two independent U(−½, ½).
      base.noise_var[i] = w * w / (6.0 * tau * tau) + kFNoiseFloorMps2 * kFNoiseFloorMps2;
    } else {
      const double floor = kAbsoluteModelErrorM + kRelativeModelError * base.prior_std[i];
      base.noise_var[i] = q * q / 12.0 + floor * floor;
    }
  }
  return base;
}

GaussianModel combine(const BaseModel& base, const std::vector<const Extension*>& extensions) {
  UncertaintyVector x_var = base.x_var;
  Eigen::Index extra = 0;
  for (const Extension* e : extensions) {
    x_var = x_var.cwiseProduct(e->x_var_scale) + e->x_var_add;
    extra += e->columns.cols();
  }
  const Eigen::Index n = base.H_x.rows();
  GaussianModel m;
  m.H.resize(n, ux::kDim + extra);
  m.prior_var.resize(ux::kDim + extra);
  m.H.leftCols(ux::kDim) = base.H_x;
  m.prior_var.head(ux::kDim) = x_var;
  m.noise_var = base.noise_var;
  m.mean = Eigen::VectorXd::Zero(n);
  Eigen::Index at = ux::kDim;
  for (const Extension* e : extensions) {
    INSMC_ASSERT(e->columns.rows() == n || e->columns.cols() == 0, "extension rows {}", e->columns.rows());
    const Eigen::Index k = e->columns.cols();
    if (k > 0) {
      m.H.middleCols(at, k) = e->columns;
      m.prior_var.segment(at, k) = e->column_var;
    }
    at += k;
    if (e->noise_var_add.size() == n) m.noise_var += e->noise_var_add;
    if (e->mean.size() == n) m.mean += e->mean;
  }
  return m;
}

}  // namespace insmc::gap
