// bounds: Table 3.1's priors too narrow for the system at hand; not an effect of
// the truth simulator but a model-level candidate (every variance scaled).
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {

Candidate bounds() {
  return {"bounds", "priors wider than Table 3.1: every uncertainty's variance times s²",
          {searched("scale", Dimension::kDimensionless, {1.5, 2, 3, 5, 10, 30, 100, 300, 1000}, 0.01, 100.0,
                    "priors 100 times narrower than Table 3.1 (below 1: pessimistic priors) to 100 times wider")},
          [](const LayoutContext&, std::span<const double> p) {
            runs::Extension e;
            e.x_var_scale = UncertaintyVector::Constant(p[0] * p[0]);
            return e;
          },
          {},
          "more runs (a prior's width is read from the run-to-run scatter)"};
}

}  // namespace insmc::gap::candidates
