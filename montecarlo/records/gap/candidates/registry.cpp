#include "montecarlo/records/gap/candidates/definitions.h"

#include <stdexcept>
#include <utility>

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

namespace {

std::vector<Candidate>& registry() {
  static std::vector<Candidate> all = [] {
    std::vector<Candidate> out;
#define INSMC_CANDIDATE(name) out.push_back(candidates::name());
#include "montecarlo/records/gap/candidates/candidate_list.h"
#undef INSMC_CANDIDATE
    return out;
  }();
  return all;
}

}  // namespace

const std::vector<Candidate>& candidate_registry() { return registry(); }

void register_candidate(Candidate candidate) {
  for (const Candidate& c : registry())
    if (c.name == candidate.name) throw std::logic_error("candidate " + c.name + " is registered already");
  registry().push_back(std::move(candidate));
}

}  // namespace insmc::gap
