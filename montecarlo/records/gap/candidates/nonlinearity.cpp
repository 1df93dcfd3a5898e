// nonlinearity: what the linear level drops (products of uncertainties,
// finite rotations); not an effect of the truth simulator but a model-level
// candidate (a model error of a share of the predicted position error).
#include <cmath>

#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {

Candidate nonlinearity() {
  return {"nonlinearity",
          "terms the linear level drops (products of uncertainties, finite rotations): a model error "
          "of a share of the predicted position error",
          {searched("share", Dimension::kDimensionless, {0.01, 0.03, 0.1, 0.3}, 1e-4, 1.0,
                    "1e-4 (second-order terms of Table 3.1's 1e-4 scale factors) to the whole predicted error, "
                    "where the linear level no longer holds")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            runs::Extension e;
            e.noise_var_add = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(ctx.layout->rows.size()));
            for (std::size_t i = 0; i < ctx.layout->rows.size(); ++i)
              if (ctx.layout->rows[i].quantity == runs::Quantity::kR)
                e.noise_var_add[static_cast<Eigen::Index>(i)] = std::pow(p[0] * ctx.base->prior_std[static_cast<Eigen::Index>(i)], 2);
            return e;
          },
          {},
          "the truth level beside the linear one (insmc run --fidelity truth) on the same samples"};
}

}  // namespace insmc::gap::candidates
