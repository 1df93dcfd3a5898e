#include "montecarlo/records/runs/files/merge_records.h"

#include <map>

#include "lib/common/input_error.h"

namespace insmc::runs {

RecordFile merge_record_files(const std::vector<RecordFile>& files, const std::vector<std::string>& names) {
  RecordFile out = files.front();
  std::map<std::int64_t, bool> ids;
  for (const RecordRun& r : out.runs) ids[r.id] = true;
  std::int64_t next = ids.empty() ? 0 : ids.rbegin()->first + 1;
  for (std::size_t f = 1; f < files.size(); ++f) {
    // A file given twice, or a copy: each run would count twice against the
    // model's run-to-run scatter.
    for (std::size_t g = 0; g < f; ++g)
      if (files[f].runs == files[g].runs)
        throw InputError("--records", names[f],
                         "holds the same runs as --records " + names[g] + ": each run is diagnosed once");
    const RecordHeader& h = files[f].header;
    const RecordHeader& h0 = files.front().header;
    if (h.latitude_deg() != h0.latitude_deg() || h.system() != h0.system() ||
        h.test_duration_s() != h0.test_duration_s() || h.scheme() != h0.scheme() ||
        h.dv_pulse_mps() != h0.dv_pulse_mps() || h.nav_start_s() != h0.nav_start_s())
      throw InputError("--records " + names[f], "header",
                       "all record files of one diagnosis must share latitude_deg, system, test_duration_s, "
                       "scheme, nav_start_s and dv_pulse_mps with " + names.front());
    for (RecordRun r : files[f].runs) {
      if (ids.count(r.id)) r.id = next;
      for (RecordRow& row : r.rows) row.run = r.id;
      ids[r.id] = true;
      next = std::max(next, r.id + 1);
      out.runs.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace insmc::runs
