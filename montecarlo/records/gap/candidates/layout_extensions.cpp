#include "montecarlo/records/gap/candidates/layout_extensions.h"

namespace insmc::gap {

LayoutExtensions::LayoutExtensions(const runs::PreparedRuns& p) : p_(&p), lattice_ctx_(p.lattices.size()) {
  for (std::size_t l = 0; l < p.lattices.size(); ++l) lattice_ctx_[l] = {&p.lattices[l], &p.site, &p.lattice_bases[l], {}};
}

std::vector<std::optional<runs::Extension>> LayoutExtensions::build(const Candidate& c, std::span<const double> theta,
                                                                    const std::vector<bool>& used) {
  const runs::PreparedRuns& p = *p_;
  // Lattices added since (a layout of the null's runs of its own): contexts
  // anew, their places may have moved.
  if (lattice_ctx_.size() != p.lattices.size()) *this = LayoutExtensions(p);
  std::vector<std::optional<runs::Extension>> on_lattice(p.lattices.size());
  for (std::size_t L = 0; L < p.layouts.size(); ++L) {
    if (!used.empty() && !used[L]) continue;
    const auto l = static_cast<std::size_t>(p.lattice_of[L]);
    if (!on_lattice[l]) on_lattice[l].emplace(c.build(lattice_ctx_[l], theta));
  }
  return on_lattice;
}

std::vector<bool> used_layouts(const runs::PreparedRuns& p) {
  std::vector<bool> used(p.layouts.size(), false);
  for (int L : p.layout_of) used[static_cast<std::size_t>(L)] = true;
  return used;
}

}  // namespace insmc::gap
