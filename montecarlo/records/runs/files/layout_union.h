#pragma once
/// Runs of one file seldom share one layout: other software drops records
/// at random, a different pattern in each run, and runs stop at different
/// times. The model of a row depends on that row alone (its time, quantity
/// and axis), so it is built once on the union of the runs' rows and each
/// layout takes its own rows from it: the model's cost follows the file's
/// distinct rows, not the number of distinct patterns.
#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "montecarlo/records/runs/files/layout.h"

namespace insmc::runs {

/// The union of layouts that share their navigation segment (nav and
/// nav_start_s): every test row of any of them, then every navigation row,
/// each stage in the order rows_within() walks (time, then f before r, then
/// axis). `layouts` must be non-empty and share the segment.
Layout layout_union(std::span<const Layout* const> layouts);

/// The indices of `layout`'s rows in `lattice`, in the layout's order, when
/// every row is there at the same stage and the layout lists each stage in
/// the union's order; nullopt otherwise.
std::optional<std::vector<Eigen::Index>> rows_within(const Layout& layout, const Layout& lattice);

}  // namespace insmc::runs
