// scale_factor_nonlinearity: a second-order accelerometer output in the
// specific force, which changes as gravity turns in the platform: a signature
// the same in every run.
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {

Candidate scale_factor_nonlinearity() {
  return {"scale_factor_nonlinearity",
          "accelerometer output k2 (f_k/g)² on every axis as the earth turns gravity in the platform, the same in "
          "every run (a design effect)",
          {amplitude("k2", Dimension::kAcceleration, 20 * kMgToMps2, "20 times Table 3.1's 1 mg bias at 1 g")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const ModelOptions m = ctx.site->model;
            const Eigen::Vector3d f0 = specific_force(0.0, m);
            const double g2 = m.gravity_mps2 * m.gravity_mps2;
            // The value at switch-over acts as a fixed bias δf through the
            // alignment (its H_x columns); the change as gravity turns is the signature.
            Eigen::VectorXd at_switch = Eigen::VectorXd::Zero(ctx.base->H_x.rows());
            for (int k = 0; k < 3; ++k) at_switch += f0[k] * f0[k] / g2 * ctx.base->H_x.col(uncertainty_slot::kAccelBias + k);
            runs::Extension e;
            e.mean = p[0] * (at_switch + signature_columns(ctx, "sfn", 1, [m, f0, g2](double t, runs::Columns3& a, runs::Columns3& th) {
                                           th.setZero();
                                           const Eigen::Vector3d f = specific_force(t, m);
                                           a.col(0) = (f.array().square() - f0.array().square()).matrix() / g2;
                                         }).col(0));
            return e;
          },
          {},
          "another orientation (a multi-position test: the error follows f squared)"};
}

}  // namespace insmc::gap::candidates
