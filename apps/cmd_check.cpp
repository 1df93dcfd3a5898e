// insmc check --bounds FILE: statistical bounds for users' CI. Runs the study
// the bounds need and exits 1 naming every bound whose upper confidence
// limit of the RMS exceeds it, 0 when all hold, 2 for a malformed file.
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <sstream>

#include "apps/cli_common.h"
#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "lib/units/units.h"
#include "montecarlo/engine/engine.h"
#include "montecarlo/write/csv.h"

namespace insmc::app {
namespace {

struct Bound {
  int line;
  std::string text;
  Scheme scheme;
  System system;
  mc::Axis axis;
  double t_s;
  double rms_limit_m;
  std::optional<double> confidence;
};

mc::Axis parse_axis(const std::string& s, const std::string& where) {
  for (mc::Axis a : mc::kAllAxes)
    if (to_string(a) == s) return a;
  throw InputError(where + " axis", s, "must be x, y, z or horizontal");
}

std::vector<Bound> read_bounds(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("--bounds", path, "cannot open the file");
  std::vector<Bound> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream tokens(line);
    std::map<std::string, std::string> kv;
    std::optional<double> limit_m;
    const std::string where = fmt::format("{}:{}:", path, n);
    for (std::string tok; tokens >> tok;) {
      for (const char* unit : {"rms_m<=", "rms_ft<="}) {
        if (tok.rfind(unit, 0) == 0) {
          const std::string v = tok.substr(std::string(unit).size());
          char* end = nullptr;
          const double x = std::strtod(v.c_str(), &end);
          if (v.empty() || *end != '\0' || !(x >= 0) || !std::isfinite(x))
            throw InputError(where + " bound", tok, "expected rms_m<=NUMBER or rms_ft<=NUMBER with NUMBER >= 0");
          limit_m = unit[4] == 'f' ? x * kFtToM : x;
        }
      }
      if (tok.rfind("rms_", 0) == 0) continue;
      const auto eq = tok.find('=');
      if (eq == std::string::npos || eq == 0)
        throw InputError(where + " token", tok, "expected key=value (scheme, system, axis, t_min, confidence) or rms_m<=N");
      kv[tok.substr(0, eq)] = tok.substr(eq + 1);
    }
    if (kv.empty() && !limit_m) continue;  // blank or comment line
    for (const char* key : {"scheme", "system", "axis", "t_min"})
      if (!kv.count(key)) throw InputError(where + " " + key, "(missing)", "each bound needs scheme, system, axis, t_min and rms_m<=N");
    if (!limit_m) throw InputError(where + " rms", "(missing)", "each bound needs rms_m<=N or rms_ft<=N");
    for (const auto& [k, v] : kv)
      if (k != "scheme" && k != "system" && k != "axis" && k != "t_min" && k != "confidence")
        throw InputError(where + " key", k, "unknown; allowed: scheme, system, axis, t_min, confidence");
    Bound b{n, line, parse_scheme(kv["scheme"], where + " scheme"), parse_system(kv["system"], where + " system"),
            parse_axis(kv["axis"], where), 0, *limit_m, std::nullopt};
    char* end = nullptr;
    b.t_s = std::strtod(kv["t_min"].c_str(), &end) * 60.0;
    if (*end != '\0' || !(b.t_s >= 0) || b.t_s > 6 * 3600.0)
      throw InputError(where + " t_min", kv["t_min"], "must be a number of minutes in [0, 360]");
    if (kv.count("confidence")) {
      const double c = std::strtod(kv["confidence"].c_str(), &end);
      if (*end != '\0' || !(c > 0 && c < 1)) throw InputError(where + " confidence", kv["confidence"], "must lie in (0, 1)");
      b.confidence = c;
    }
    out.push_back(b);
  }
  if (out.empty()) throw InputError("--bounds", path, "holds no bound");
  return out;
}

}  // namespace

int run_check(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("bounds", po::value<std::string>(),
                     "file of bounds, one a line: scheme=none system=2 axis=horizontal t_min=84 "
                     "rms_m<=9000 [confidence=0.95]; rms_ft also accepted; # comments");
  opts.add(study_options_description(true));
  const auto vm = parse_args(args, "check", "--bounds FILE [study options]", opts);
  if (!vm) return 0;
  if (!vm->count("bounds")) throw InputError("--bounds", "(missing)", "give the file of bounds to check");
  const std::vector<Bound> bounds = read_bounds((*vm)["bounds"].as<std::string>());
  mc::StudyConfig config = read_study_config(*vm, true);
  // Run exactly what the bounds need: their systems, schemes and times.
  config.systems.clear();
  config.schemes.clear();
  config.report_times_s.clear();
  config.with_grid = false;
  for (const Bound& b : bounds) {
    if (std::find(config.systems.begin(), config.systems.end(), b.system) == config.systems.end())
      config.systems.push_back(b.system);
    if (std::find(config.schemes.begin(), config.schemes.end(), b.scheme) == config.schemes.end())
      config.schemes.push_back(b.scheme);
    if (std::find(config.report_times_s.begin(), config.report_times_s.end(), b.t_s) == config.report_times_s.end())
      config.report_times_s.push_back(b.t_s);
  }
  mc::validate(config);
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);
  const mc::StudyAccumulator acc = mc::run_blocks(config, map, 0, mc::block_count(config.samples));
  int violated = 0;
  for (const Bound& b : bounds) {
    for (size_t o = 0; o < layout.outputs.size(); ++o) {
      const auto& s = layout.outputs[o];
      if (s.scheme != b.scheme || s.system != b.system || s.axis != b.axis ||
          std::abs(layout.times_s[s.time_index] - b.t_s) > 1e-6)
        continue;
      const double conf = b.confidence.value_or(config.confidence);
      const mc::OutputSummary sum = acc.outputs()[o].summarize(conf);
      const bool ok = sum.rms_hi <= b.rms_limit_m;
      if (!ok) ++violated;
      fmt::print("{} line {}: scheme={} system={} axis={} t_min={}: RMS {} m, upper {}% limit {} m {} bound {} m\n",
                 ok ? "ok      " : "VIOLATED", b.line, to_string(b.scheme), system_number(b.system),
                 to_string(b.axis), mc::format_number(b.t_s / 60), mc::format_number(sum.rms),
                 mc::format_number(100 * conf), mc::format_number(sum.rms_hi), ok ? "<=" : ">",
                 mc::format_number(b.rms_limit_m));
    }
  }
  if (violated) fmt::print(stderr, "insmc check: {} of {} bounds violated\n", violated, bounds.size());
  return violated ? 1 : 0;
}

}  // namespace insmc::app
