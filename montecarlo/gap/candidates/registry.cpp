#include "montecarlo/gap/candidates/definitions.h"

namespace insmc::gap {

int Candidate::grid_size() const {
  int n = 1;
  for (const CandidateParameter& p : parameters)
    if (!p.amplitude) n *= static_cast<int>(p.grid.size());
  return n;
}

std::vector<double> Candidate::grid_point(int index) const {
  std::vector<double> v(parameters.size(), 0.0);
  for (std::size_t i = parameters.size(); i-- > 0;) {
    if (parameters[i].amplitude) continue;
    const int n = static_cast<int>(parameters[i].grid.size());
    v[i] = parameters[i].grid[static_cast<std::size_t>(index % n)];
    index /= n;
  }
  return v;
}

std::vector<int> Candidate::amplitude_indices() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (parameters[i].amplitude) out.push_back(static_cast<int>(i));
  return out;
}

/// Keep the order: equal held-out gaps keep it in the ranking (a stable
/// sort), so another order changes the report.
const std::vector<Candidate>& candidate_registry() {
  static const std::vector<Candidate> all = {
      candidates::bounds(),
      candidates::quantization(),
      candidates::sway(),
      candidates::accel_bias_instability(),
      candidates::gyro_drift_instability(),
      candidates::angle_random_walk(),
      candidates::velocity_random_walk(),
      candidates::thermal_transient(),
      candidates::anisoelastic_drift(),
      candidates::scale_factor_nonlinearity(),
      candidates::deflection_of_vertical(),
      candidates::gravity_model(),
      candidates::alignment_transient(),
      candidates::switch_transient(),
      candidates::nonlinearity(),
  };
  return all;
}

}  // namespace insmc::gap
