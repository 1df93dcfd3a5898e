#pragma once
/// What a record writer (`simulate`, `import-imu`) may write: a file its
/// own readers take, within the work budget of docs/robustness.md. The
/// rows are known from the options before any work (runs × the times of a
/// run), so a file beyond the budget is refused with the option that sets
/// it and the largest value that fits, never after the work.
#include <cmath>
#include <cstddef>
#include <fmt/format.h>
#include <string>

#include "lib/common/input_error.h"
#include "lib/records/record_io.h"

namespace insmc {

/// Rows a writer builds in one file: 1.6 million. The writer holds every
/// row (104 bytes), the whole text it writes (~130 bytes a row) and what
/// made the rows at once. Measured (docs/robustness.md, "Work budgets"):
/// `simulate` peaks at 0.91 GB for 1,992,720 rows, `import-imu` at 1.11 GB
/// for 1,969,000 rows and 0.78 GB for 1,575,000 (about 500 bytes a row), so
/// 1.6 million rows stay under 0.8 GB. Below the readers' 4 million
/// (record_io.h): gap and compensate take every file a writer writes.
inline constexpr std::size_t kMaxWrittenRecordRows = 1'600'000;

/// `x` rounded up to three significant digits (a bound given in a message).
inline double round_up_3(double x) {
  if (!(x > 0) || !std::isfinite(x)) return x;
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2);
  return std::ceil(x / unit * (1 - 1e-12)) * unit;
}
static_assert(kMaxWrittenRecordRows <= kMaxRecordRows, "a writer writes only files its readers take");

/// Throws InputError naming `option` = `value` when `runs` runs of
/// `rows_per_run` rows each exceed kMaxWrittenRecordRows: `what` says what
/// makes a run's rows (e.g. "1min of test run and 6h of navigation at
/// 0.5s"), `fits` what value of the option would fit.
inline void check_written_rows(const std::string& option, const std::string& value, std::size_t runs,
                               std::size_t rows_per_run, const std::string& what, const std::string& fits) {
  const double rows = static_cast<double>(runs) * static_cast<double>(rows_per_run);
  if (rows <= static_cast<double>(kMaxWrittenRecordRows)) return;
  throw InputError(option, value,
                   fmt::format("{} run{} of {} rows ({}) make {:.0f} rows; a record file holds at most {} rows "
                               "(1 GB while it is written): {}",
                               runs, runs == 1 ? "" : "s", rows_per_run, what, rows, kMaxWrittenRecordRows, fits));
}

}  // namespace insmc
