#pragma once
/// A candidate's extension for the layouts of prepared runs: built once on
/// each lattice (runs/prepared_runs.h), whose rows every layout cut from it
/// takes, so the cost follows the file's distinct rows, not its patterns of
/// missing records. The lattices' contexts keep the candidate's unit
/// responses (LayoutContext::cache) for every later point of its grid.
#include <optional>
#include <span>
#include <vector>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

class LayoutExtensions {
 public:
  /// For one candidate at a time (the cache is the candidate's; not shared
  /// across threads).
  explicit LayoutExtensions(const runs::PreparedRuns& p);

  /// The extension of `c` at `theta` on each lattice some layout L with
  /// used[L] (any layout when `used` is empty) takes its rows from; the
  /// others left empty. A layout's own rows: runs::select_rows with
  /// p.lattice_rows[L].
  std::vector<std::optional<runs::Extension>> build(const Candidate& c, std::span<const double> theta,
                                                    const std::vector<bool>& used = {});

 private:
  const runs::PreparedRuns* p_;
  std::vector<LayoutContext> lattice_ctx_;
};

/// Which layouts some run of `p` is analysed under.
std::vector<bool> used_layouts(const runs::PreparedRuns& p);

}  // namespace insmc::gap
