// gravity_model: the computer's gravitation differs from the true one: a
// site offset fixed to the earth and a vertical anomaly only r sees.
#include <string>

#include "lib/frames/frames.h"
#include "lib/units/units.h"
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/runs/model/response.h"

namespace insmc::gap::candidates {

Candidate gravity_model() {
  return {"gravity_model",
          "the computer's gravitation differs from the true one (e.g. J2), the same in every run at a site: the "
          "computer places the site where its own model has the plumb line the leveling found, an offset fixed "
          "to the earth (north, down; turning with it in a'), and lacks a vertical anomaly that drives r",
          {amplitude("north_offset", Dimension::kLength, 1000e3, "the 1000 km of lib/units/physical_range.h"),
           amplitude("down_offset", Dimension::kLength, 1000e3, "the 1000 km of lib/units/physical_range.h"),
           amplitude("vertical", Dimension::kAcceleration, 100 * kMgToMps2,
                     "the 100 mg the linearized model describes")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const ModelOptions m = ctx.site->model;
            runs::InputSignal in;
            in.columns = 1;
            in.f_responds = false;
            // (3.24): the computer lacks δg_D, fixed to the earth: u = C(t) (0, 0, δg_D);
            // f is measured against the leveled plumb line, so only r sees it.
            in.at = [m](double t, runs::Columns3& a, runs::Columns3& th) {
              th.setZero();
              a.col(0) = C_ap_n(m.latitude_rad, m.earth_rate_radps * t).col(2);
            };
            const auto key = std::string("vertical_anomaly");
            if (!ctx.cache.count(key)) ctx.cache[key] = input_response(*ctx.layout, *ctx.site, in);
            runs::Extension e;
            e.mean = p[2] * ctx.cache[key].col(0);
            // The site offset: a position error fixed to the earth, r(t) = C(t) (d_N, 0, d_D) in a'.
            for (std::size_t i = 0; i < ctx.layout->rows.size(); ++i) {
              const runs::ObservationRow& row = ctx.layout->rows[i];
              if (row.quantity != runs::Quantity::kR) continue;
              const Eigen::Matrix3d C = C_ap_n(m.latitude_rad, m.earth_rate_radps * row.t_s);
              e.mean[static_cast<Eigen::Index>(i)] += p[0] * C(row.axis, 0) + p[1] * C(row.axis, 2);
            }
            return e;
          },
          {},
          "a second site at another latitude"};
}

}  // namespace insmc::gap::candidates
