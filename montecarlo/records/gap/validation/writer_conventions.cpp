#include "montecarlo/records/gap/validation/writer_conventions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "lib/units/units.h"
#include "montecarlo/records/runs/simulation/record_simulation.h"
#include "montecarlo/study/random/philox.h"

namespace insmc::gap {
namespace {

/// x to 9 significant digits, as a writer printing "%.9g" leaves it.
double nine_digits(double x) { return x == 0.0 || !std::isfinite(x) ? x : std::stod(fmt::format("{:.9g}", x)); }

bool on_grid(double t_s, double every_s) { return std::abs(t_s / every_s - std::round(t_s / every_s)) < 1e-9; }

}  // namespace

std::string WriterConventions::describe() const {
  std::string d = fmt::format("f every {:g} s, r every {:g} s, {}{}", f_every_s, r_every_s,
                              pulses ? "0.1 ft/s pulses" : "continuous f", zero_row ? ", a row at t = 0" : "");
  if (dropout_max > 0) d += fmt::format(", dropouts up to {:.1f} % per run", 100.0 * dropout_max);
  if (!f_in_nav) d += ", no f after the test";
  if (resolution_m >= 0) d += resolution_m > 0 ? fmt::format(", r to {:.3g} m", resolution_m) : ", r exact";
  if (short_from_s >= 0) d += fmt::format(", {:.0f} % of runs stop early", 100.0 * short_share);
  if (header_keys) d += ", optional header keys given";
  return d;
}

WriterConventions foreign_conventions_of(std::uint64_t file_seed, bool needs_pulses) {
  WriterConventions l;
  l.f_every_s = std::array{5.0, 10.0, 20.0}[file_seed % 3];
  l.r_every_s = std::array{10.0, 30.0, 60.0}[(file_seed / 3) % 3];
  l.pulses = needs_pulses || (file_seed / 9) % 2 == 0;
  l.zero_row = (file_seed / 2) % 2 == 1;
  return l;
}

WriterConventions fuzzed_conventions_of(std::uint64_t file_seed, bool needs_pulses, double test_duration_s) {
  // The file's own stream, apart from every run's (their index is below 2^40).
  mc::CounterStream u(file_seed, mc::Stream::Measurement, std::uint64_t{3} << 40);
  WriterConventions l;
  l.f_every_s = 1.0 + std::floor(60.0 * u.uniform01());
  l.r_every_s = 1.0 + std::floor(60.0 * u.uniform01());
  l.pulses = needs_pulses || u.uniform01() < 0.5;
  l.zero_row = u.uniform01() < 0.5;
  l.dropout_max = 0.1 * u.uniform01();
  l.f_in_nav = u.uniform01() < 0.5;
  // Exact in a quarter of the files, else log-uniform from 0.1 mm to 3 ft.
  const double exact = u.uniform01(), scale = u.uniform01();
  l.resolution_m = exact < 0.25 ? 0.0 : 1e-4 * std::pow(3.0 * kFtToM / 1e-4, scale);
  l.short_share = std::array{0.0, 0.1, 1.0 / 3.0, 0.5}[static_cast<std::size_t>(4.0 * u.uniform01()) % 4];
  l.short_from_s = 0.5 * test_duration_s;
  l.header_keys = u.uniform01() < 0.5;
  return l;
}

RecordFile simulate_foreign_file(TruthOptions truth, const mc::Sampler& sampler, std::uint64_t seed, const ForeignRuns& spec,
                                 const WriterConventions& conventions) {
  truth.filter_interval_s = conventions.f_every_s;
  truth.dv_pulse_mps = conventions.pulses ? TruthOptions{}.dv_pulse_mps : 0.0;
  const double T = spec.test_duration_s, nav = spec.nav_duration_s;
  RecordFile file;
  file.header.entries = {{"recorder", "acme-logger 2.3"}, {"scheme", "none"}, {"site.name", "hangar 4"}};
  file.header.set("latitude_deg", truth.model.latitude_rad / kDegToRad);
  file.header.set("test_duration_s", T);
  file.header.set("system", truth.system == System::kTheodolite ? "1" : "2");
  file.header.set("operator", "night shift");
  const double resolution_m = conventions.resolution_m >= 0 ? conventions.resolution_m : spec.position_resolution_m;
  if (conventions.header_keys) {
    file.header.set("dv_pulse_mps", truth.dv_pulse_mps);
    file.header.set("filter_interval_s", truth.filter_interval_s);
    file.header.set("position_resolution_m", resolution_m);
  }
  // The union of the two grids; f only on its own.
  std::vector<double> grid;
  for (const double every : {conventions.f_every_s, conventions.r_every_s})
    for (int k = 1; k * every <= T + nav + 1e-9; ++k) grid.push_back(k * every);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), grid.end());
  for (int r = 0; r < spec.runs; ++r) {
    // A third of the runs stop 60-80 min into the navigation, at a time of
    // the run's own stream (not the simulator's).
    double end = T + nav;
    mc::CounterStream stream(seed, mc::Stream::Measurement, (std::uint64_t{1} << 40) + static_cast<std::uint64_t>(r));
    if (conventions.short_from_s < 0) {
      if (r % 3 == 2 && nav > 4800.0) end = T + 3600.0 + 1200.0 * stream.uniform01();
    } else if (stream.uniform01() < conventions.short_share) {
      end = conventions.short_from_s + (T + nav - conventions.short_from_s) * stream.uniform01();
    }
    std::vector<double> times;
    if (conventions.zero_row) times.push_back(0.0);  // the switch-over itself: r, no complete f window
    for (const double t : grid)
      if (t <= end + 1e-9) times.push_back(t);
    RecordRun run = runs::simulate_record_run(truth, sampler, seed, static_cast<std::uint64_t>(r), times,
                                        {T, resolution_m});
    run.id = 100 + 7 * static_cast<std::int64_t>(r);
    // The run's own dropouts (its stream goes on from the stop time's draw).
    const double dropout = conventions.dropout_max * stream.uniform01();
    for (RecordRow& row : run.rows) {
      row.run = run.id;
      if (!on_grid(row.t_s, conventions.f_every_s) || (!conventions.f_in_nav && row.phase != Phase::kTest)) row.f_mps2 = {};
      if (dropout > 0 && stream.uniform01() < dropout) row.f_mps2 = {};
      // r is on every row of a record (docs/records.md): a lost r sample is a lost row.
      if (dropout > 0 && stream.uniform01() < dropout) row.r_ap_m.reset();
      for (OptionalValue& f : row.f_mps2)
        if (f) f = nine_digits(*f);
      if (row.r_ap_m) {
        const Eigen::Vector3d p = *row.r_ap_m;
        row.r_ap_m = Eigen::Vector3d(nine_digits(p[0]), nine_digits(p[1]), nine_digits(p[2]));
      }
    }
    std::erase_if(run.rows, [](const RecordRow& row) { return !row.r_ap_m; });
    file.runs.push_back(std::move(run));
  }
  return file;
}

}  // namespace insmc::gap
