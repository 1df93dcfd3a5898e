#include "montecarlo/records/gap/where/unread_rows.h"

#include <fmt/format.h>

#include <algorithm>
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace insmc::gap {
namespace {

/// Values written with a few significant figures (other software's files)
/// move each by up to this share of their size: the resolution of a
/// "continuous" record.
constexpr double kWrittenFigures = 1e-6;

/// How far beyond the reach of the resolution and the curvature a value
/// must lie to be listed: the curvature is read off the read rows, which
/// can miss a turn between them (on fuzzed null files values
/// left a twice-reach line by up to 1.3 times); a corrupt value lies orders
/// beyond.
constexpr double kReach = 10.0;

struct RRow {
  double t_s;
  Eigen::Vector3d r_m;
  bool read;
};

/// Each read row's second difference (its neighbours' where it has one
/// side only), per axis: the curvature's reach between read rows; infinite
/// with fewer than three read rows (nothing to screen against).
std::vector<Eigen::Vector3d> accelerations(const std::vector<RRow>& rows, const std::vector<std::size_t>& read) {
  if (read.size() < 3)
    return std::vector<Eigen::Vector3d>(read.size(), Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()));
  std::vector<Eigen::Vector3d> out(read.size());
  for (std::size_t j = 0; j < read.size(); ++j) {
    const std::size_t c = std::clamp<std::size_t>(j, 1, read.size() - 2);
    const RRow &a = rows[read[c - 1]], &b = rows[read[c]], &e = rows[read[c + 1]];
    const Eigen::Vector3d slope_before = (b.r_m - a.r_m) / (b.t_s - a.t_s);
    const Eigen::Vector3d slope_after = (e.r_m - b.r_m) / (e.t_s - b.t_s);
    out[j] = (2.0 * (slope_after - slope_before) / (e.t_s - a.t_s)).cwiseAbs();
  }
  return out;
}

}  // namespace

UnreadRows screen_unread_rows(const RecordFile& file, const std::vector<runs::RunData>& runs, double resolution_m) {
  UnreadRows out;
  std::map<std::int64_t, const runs::RunData*> by_id;
  for (const runs::RunData& r : runs) by_id[r.id] = &r;
  std::vector<UnreadRow> beyond;
  std::set<std::int64_t> runs_beyond;
  for (const RecordRun& record : file.runs) {
    const auto found = by_id.find(record.id);
    if (found == by_id.end()) continue;
    std::vector<double> read_t;
    for (const runs::ObservationRow& o : found->second->layout.rows)
      if (o.quantity == runs::Quantity::kR && o.axis == 0) read_t.push_back(o.t_s);
    std::sort(read_t.begin(), read_t.end());
    std::vector<RRow> rows;
    std::vector<std::size_t> read;
    for (const RecordRow& row : record.rows) {
      if (row.phase == Phase::kAlign || !row.r_ap_m) continue;
      const bool is_read = std::binary_search(read_t.begin(), read_t.end(), row.t_s);
      if (is_read) read.push_back(rows.size());
      rows.push_back({row.t_s, *row.r_ap_m, is_read});
    }
    out.read += static_cast<int>(read.size());
    out.unread += static_cast<int>(rows.size() - read.size());
    const std::vector<Eigen::Vector3d> acc = accelerations(rows, read);
    // Each unread row between two read rows, against the line through them.
    std::size_t next = 0;  // index into read of the first read row after i
    for (std::size_t i = 0; i < rows.size(); ++i) {
      while (next < read.size() && read[next] <= i) ++next;
      if (rows[i].read || next == 0 || next == read.size()) continue;
      const RRow &a = rows[read[next - 1]], &b = rows[read[next]], &x = rows[i];
      const double w = (x.t_s - a.t_s) / (b.t_s - a.t_s);
      for (int k = 0; k < 3; ++k) {
        const double line = a.r_m[k] + w * (b.r_m[k] - a.r_m[k]);
        const double size = std::max({std::abs(a.r_m[k]), std::abs(b.r_m[k]), std::abs(x.r_m[k])});
        const double q = std::max(resolution_m, kWrittenFigures * size);
        const double a_max = std::max(acc[next - 1][k], acc[next][k]);
        const double bound = kReach * (q + a_max * (x.t_s - a.t_s) * (b.t_s - x.t_s) / 2.0);
        const double deviation = x.r_m[k] - line;
        if (!(std::abs(deviation) > bound)) continue;
        beyond.push_back({record.id, x.t_s, fmt::format("r_{}", "xyz"[k]), deviation, bound});
        runs_beyond.insert(record.id);
      }
    }
  }
  out.beyond = static_cast<int>(beyond.size());
  out.runs_beyond = static_cast<int>(runs_beyond.size());
  out.runs = static_cast<int>(runs.size());
  std::sort(beyond.begin(), beyond.end(), [](const UnreadRow& l, const UnreadRow& r) {
    return std::abs(l.deviation_m) / l.bound_m > std::abs(r.deviation_m) / r.bound_m;
  });
  beyond.resize(std::min<std::size_t>(beyond.size(), kListedUnread));
  out.largest = std::move(beyond);
  return out;
}

bool unread_rows_isolated(const UnreadRows& u) {
  return u.runs_beyond > 0 && u.runs_beyond <= std::max(1, u.runs / 10);
}

namespace {

std::string farthest(const UnreadRows& u) {
  const UnreadRow& l = u.largest.front();
  return fmt::format("the farthest: run {} at t = {:g} s, {} {:.3g} m off, bound {:.3g} m", l.run, l.t_s, l.component,
                     l.deviation_m, l.bound_m);
}

const char* leaves(int values) { return values == 1 ? "leaves" : "leave"; }

}  // namespace

std::string unread_rows_sentence(const UnreadRows& u) {
  if (u.unread == 0) return "";
  const runs::ExtractionOptions spacing;
  std::string s = fmt::format(
      "r is read one row per {:g} s of the test run and per {:g} s after: {} of {} r rows are compared with the model; "
      "the other {} were screened against the straight line through the read rows beside them (within ten times the "
      "resolution's and the read rows' curvature's reach): ",
      spacing.r_spacing_s, spacing.nav_r_spacing_s, u.read, u.read + u.unread, u.unread);
  if (u.beyond == 0) return s + "none leaves it";
  return s + fmt::format("{} {} it in {} of {} runs ({}): values the model never compares, corrupt or moving faster "
                         "than the read spacing",
                         u.beyond, leaves(u.beyond), u.runs_beyond, u.runs, farthest(u));
}

std::string unread_rows_finding(const UnreadRows& u) {
  if (!unread_rows_isolated(u)) return "";
  const std::string values = u.beyond == 1 ? std::string("An r value") : fmt::format("{} r values", u.beyond);
  const std::string in_runs = u.runs_beyond == 1 ? std::string("one run") : fmt::format("{} runs", u.runs_beyond);
  return fmt::format("{} of {} that the model does not read {} the line through the rows it reads ({}): a corrupt "
                     "record.",
                     values, in_runs, leaves(u.beyond), farthest(u));
}

}  // namespace insmc::gap
