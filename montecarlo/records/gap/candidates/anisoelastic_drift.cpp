// anisoelastic_drift: g²-sensitive gyro drift, driven by gravity turning in
// the platform as the earth turns: a signature the same in every run.
#include <algorithm>
#include <functional>
#include <vector>

#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {
namespace {

/// ∫_0^t of a smooth vector function by a table at 10 s (Simpson per step), linear between.
class IntegralTable {
 public:
  IntegralTable(const std::function<Eigen::Vector3d(double)>& f, double end_s) {
    values_.push_back(Eigen::Vector3d::Zero());
    for (double t = 0; t < end_s + kStep; t += kStep)
      values_.push_back(values_.back() + kStep / 6.0 * (f(t) + 4.0 * f(t + kStep / 2) + f(t + kStep)));
  }
  Eigen::Vector3d at(double t) const {
    const double u = std::clamp(t / kStep, 0.0, static_cast<double>(values_.size() - 1) - 1e-9);
    const auto i = static_cast<std::size_t>(u);
    const double w = u - static_cast<double>(i);
    return (1 - w) * values_[i] + w * values_[std::min(i + 1, values_.size() - 1)];
  }
 private:
  static constexpr double kStep = 10.0;
  std::vector<Eigen::Vector3d> values_;
};

}  // namespace

Candidate anisoelastic_drift() {
  return {"anisoelastic_drift",
          "g²-sensitive drift ω = c (f_y f_z, f_z f_x, f_x f_y)/g² as the earth turns gravity in the platform, the "
          "same in every run (a design effect)",
          {amplitude("coefficient", Dimension::kAngularRate, 1000 * kMeruToRadps,
                     "100 times Table 3.1's 10 meru drift, a tenth of the small-angle model's limit")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const ModelOptions m = ctx.site->model;
            const double g2 = m.gravity_mps2 * m.gravity_mps2;
            const IntegralTable theta(
                [&](double t) -> Eigen::Vector3d {
                  const Eigen::Vector3d f = specific_force(t, m);
                  return Eigen::Vector3d(f.y() * f.z(), f.z() * f.x(), f.x() * f.y()) / g2;
                },
                layout_end(*ctx.layout) + 60.0);
            runs::Extension e;
            e.mean = p[0] * signature_columns(ctx, "anisoelastic", 1, [&](double t, runs::Columns3& a, runs::Columns3& th) {
                              a.setZero();
                              th.col(0) = theta.at(t);
                            }).col(0);
            return e;
          },
          {},
          "another orientation (the drift follows products of the specific-force components)"};
}

}  // namespace insmc::gap::candidates
