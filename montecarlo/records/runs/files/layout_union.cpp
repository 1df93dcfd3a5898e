#include "montecarlo/records/runs/files/layout_union.h"

#include <algorithm>
#include <tuple>

#include "lib/common/assert.h"

namespace insmc::runs {
namespace {

auto order_key(const ObservationRow& r) { return std::tuple(r.t_s, static_cast<int>(r.quantity), r.axis); }

bool before(const ObservationRow& a, const ObservationRow& b) { return order_key(a) < order_key(b); }

}  // namespace

Layout layout_union(std::span<const Layout* const> layouts) {
  INSMC_ASSERT(!layouts.empty(), "union of no layouts");
  Layout out;
  out.nav = layouts.front()->nav;
  out.nav_start_s = layouts.front()->nav_start_s;
  std::vector<ObservationRow> test, nav;
  for (const Layout* l : layouts) {
    INSMC_ASSERT(l->nav == out.nav && l->nav_start_s == out.nav_start_s, "union of layouts of other segments");
    test.insert(test.end(), l->rows.begin(), l->rows.begin() + l->test_rows);
    nav.insert(nav.end(), l->rows.begin() + l->test_rows, l->rows.end());
  }
  for (auto* stage : {&test, &nav}) {
    std::sort(stage->begin(), stage->end(), before);
    stage->erase(std::unique(stage->begin(), stage->end(),
                             [](const ObservationRow& a, const ObservationRow& b) { return order_key(a) == order_key(b); }),
                 stage->end());
  }
  out.test_rows = static_cast<int>(test.size());
  out.rows = std::move(test);
  out.rows.insert(out.rows.end(), nav.begin(), nav.end());
  return out;
}

std::optional<std::vector<Eigen::Index>> rows_within(const Layout& layout, const Layout& lattice) {
  if (layout.nav != lattice.nav || layout.nav_start_s != lattice.nav_start_s) return std::nullopt;
  std::vector<Eigen::Index> at;
  at.reserve(layout.rows.size());
  // Each stage walks its part of the lattice once: the layout's rows must
  // come in the same order, so a row not found by the time the lattice
  // passes it is not there.
  const auto walk = [&](std::size_t from, std::size_t to, std::size_t lattice_from, std::size_t lattice_to) {
    std::size_t j = lattice_from;
    for (std::size_t i = from; i < to; ++i) {
      const auto key = order_key(layout.rows[i]);
      while (j < lattice_to && order_key(lattice.rows[j]) < key) ++j;
      if (j == lattice_to || order_key(lattice.rows[j]) != key || lattice.rows[j].group != layout.rows[i].group)
        return false;
      at.push_back(static_cast<Eigen::Index>(j++));
    }
    return true;
  };
  const auto test = static_cast<std::size_t>(layout.test_rows), lattice_test = static_cast<std::size_t>(lattice.test_rows);
  if (!walk(0, test, 0, lattice_test) || !walk(test, layout.rows.size(), lattice_test, lattice.rows.size()))
    return std::nullopt;
  return at;
}

}  // namespace insmc::runs
