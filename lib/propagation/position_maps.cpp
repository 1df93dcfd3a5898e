#include "lib/propagation/position_maps.h"

#include "lib/common/assert.h"
#include "lib/frames/frames.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"

namespace insmc {

std::vector<Sensitivity3> position_maps(System system, Fidelity fidelity, const ModelOptions& o,
                                        const std::vector<double>& times_s) {
  if (fidelity == Fidelity::kPaper) {
    const ShortRunMatrices m = paper_short_run_matrices(system, o);
    std::vector<Sensitivity3> out;
    out.reserve(times_s.size());
    for (double t : times_s) out.push_back(short_run_position_map(m, t, o));
    return out;
  }
  INSMC_ASSERT(fidelity == Fidelity::kLinear, "position_maps: fidelity {} is not linear in x",
               to_string(fidelity));
  return linear_position_maps(LinearErrorModel(system, o), times_s);
}

Eigen::Matrix<double, 2, 3> local_level_horizontal(double t_s, const ModelOptions& o) {
  const Mat3 c_n_ap = C_ap_n(o.latitude_rad, o.earth_rate_radps * t_s).transpose();
  return c_n_ap.topRows<2>();
}

}  // namespace insmc
