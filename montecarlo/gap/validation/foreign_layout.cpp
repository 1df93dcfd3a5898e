#include "montecarlo/gap/validation/foreign_layout.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "lib/units/units.h"
#include "montecarlo/runs/simulation/record_simulation.h"
#include "montecarlo/random/philox.h"

namespace insmc::gap {
namespace {

/// x to 9 significant digits, as a writer printing "%.9g" leaves it.
double nine_digits(double x) { return x == 0.0 || !std::isfinite(x) ? x : std::stod(fmt::format("{:.9g}", x)); }

bool on_grid(double t_s, double every_s) { return std::abs(t_s / every_s - std::round(t_s / every_s)) < 1e-9; }

}  // namespace

std::string ForeignLayout::describe() const {
  return fmt::format("f every {:g} s, r every {:g} s, {}{}", f_every_s, r_every_s,
                     pulses ? "0.1 ft/s pulses" : "continuous f", zero_row ? ", a row at t = 0" : "");
}

ForeignLayout foreign_layout_of(std::uint64_t file_seed, bool needs_pulses) {
  ForeignLayout l;
  l.f_every_s = std::array{5.0, 10.0, 20.0}[file_seed % 3];
  l.r_every_s = std::array{10.0, 30.0, 60.0}[(file_seed / 3) % 3];
  l.pulses = needs_pulses || (file_seed / 9) % 2 == 0;
  l.zero_row = (file_seed / 2) % 2 == 1;
  return l;
}

RecordFile simulate_foreign_file(TruthOptions truth, const mc::Sampler& sampler, std::uint64_t seed, const ForeignRuns& spec,
                                 const ForeignLayout& layout) {
  truth.filter_interval_s = layout.f_every_s;
  truth.dv_pulse_mps = layout.pulses ? TruthOptions{}.dv_pulse_mps : 0.0;
  const double T = spec.test_duration_s, nav = spec.nav_duration_s;
  RecordFile file;
  file.header.entries = {{"recorder", "acme-logger 2.3"}, {"scheme", "none"}, {"site.name", "hangar 4"}};
  file.header.set("latitude_deg", truth.model.latitude_rad / kDegToRad);
  file.header.set("test_duration_s", T);
  file.header.set("system", truth.system == System::kTheodolite ? "1" : "2");
  file.header.set("operator", "night shift");
  // The union of the two grids; f only on its own.
  std::vector<double> grid;
  for (const double every : {layout.f_every_s, layout.r_every_s})
    for (int k = 1; k * every <= T + nav + 1e-9; ++k) grid.push_back(k * every);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), grid.end());
  for (int r = 0; r < spec.runs; ++r) {
    // A third of the runs stop 60-80 min into the navigation, at a time of
    // the run's own stream (not the simulator's).
    double end = T + nav;
    if (r % 3 == 2 && nav > 4800.0) {
      mc::CounterStream stream(seed, mc::Stream::Measurement, (std::uint64_t{1} << 40) + static_cast<std::uint64_t>(r));
      end = T + 3600.0 + 1200.0 * stream.uniform01();
    }
    std::vector<double> times;
    if (layout.zero_row) times.push_back(0.0);  // the switch-over itself: r, no complete f window
    for (const double t : grid)
      if (t <= end + 1e-9) times.push_back(t);
    RecordRun run = runs::simulate_record_run(truth, sampler, seed, static_cast<std::uint64_t>(r), times,
                                        {T, spec.position_resolution_m});
    run.id = 100 + 7 * static_cast<std::int64_t>(r);
    for (RecordRow& row : run.rows) {
      row.run = run.id;
      if (!on_grid(row.t_s, layout.f_every_s)) row.f_mps2 = {};
      for (OptionalValue& f : row.f_mps2)
        if (f) f = nine_digits(*f);
      if (row.r_ap_m) {
        const Eigen::Vector3d p = *row.r_ap_m;
        row.r_ap_m = Eigen::Vector3d(nine_digits(p[0]), nine_digits(p[1]), nine_digits(p[2]));
      }
    }
    file.runs.push_back(std::move(run));
  }
  return file;
}

}  // namespace insmc::gap
