#include "montecarlo/study/write/accuracy_cells.h"

#include <array>
#include <cmath>
#include <fmt/format.h>

#include "montecarlo/report/csv.h"
#include "montecarlo/report/interval_format.h"

namespace insmc::mc {
namespace {

struct Metric {
  const char* name;
  const char* readable;  // envelope.md's name
  bool is_length;        // otherwise the rate, in n.mi./h
};
constexpr std::array<Metric, 4> kMetrics = {{{"cep50", "CEP50", true},
                                             {"cep95", "CEP95", true},
                                             {"drms2", "2DRMS", true},
                                             {"radial_rate", "CEP50/t", false}}};
constexpr std::array<const char*, 3> kParts = {"", "_lo", "_hi"};  // the value, its interval's ends

/// The metric's estimate in its printed unit.
std::array<double, 3> printed(const HorizontalAccuracy& a, std::size_t metric, double length_k) {
  const std::array<const QuantileEstimate*, 4> estimates = {&a.cep50_m, &a.cep95_m, &a.drms2_m, &a.radial_rate_mps};
  const QuantileEstimate& e = *estimates[metric];
  if (!kMetrics[metric].is_length) return {mps_to_nmiph(e.value), mps_to_nmiph(e.lo), mps_to_nmiph(e.hi)};
  return {length_k * e.value, length_k * e.lo, length_k * e.hi};
}

}  // namespace

// n.mi./h = (m/s) · (s per hour) / (m per n.mi.).
double mps_to_nmiph(double v_mps) { return v_mps * kHourToS / kNmiToM; }

std::vector<std::string> accuracy_header(LengthUnit unit) {
  std::vector<std::string> out;
  for (const Metric& m : kMetrics)
    for (const char* part : kParts)
      out.push_back(fmt::format("{}{}_{}", m.name, part, m.is_length ? length_suffix(unit) : "nmiph"));
  return out;
}

std::vector<std::string> accuracy_cells(const std::optional<HorizontalAccuracy>& a, LengthUnit unit) {
  std::vector<std::string> out;
  for (std::size_t m = 0; m < kMetrics.size(); ++m) {
    const std::array<double, 3> v = a ? printed(*a, m, length_factor(unit)) : std::array<double, 3>{NAN, NAN, NAN};
    for (const double x : v) out.push_back(std::isnan(x) ? "" : format_number(x));
  }
  return out;
}

std::vector<std::string> readable_accuracy_header(LengthUnit unit) {
  std::vector<std::string> out;
  for (const Metric& m : kMetrics)
    out.push_back(fmt::format("{} [{}]", m.readable, m.is_length ? length_suffix(unit) : "n.mi./h"));
  return out;
}

std::vector<std::string> readable_accuracy_cells(const std::optional<HorizontalAccuracy>& a, LengthUnit unit) {
  std::vector<std::string> out;
  for (std::size_t m = 0; m < kMetrics.size(); ++m) {
    if (!a) {
      out.emplace_back();
      continue;
    }
    const std::array<double, 3> v = printed(*a, m, length_factor(unit));
    // Half the interval's width (percentile intervals are not symmetric).
    out.push_back(std::isnan(v[0]) ? "" : format_with_interval(v[0], 0.5 * (v[2] - v[1])));
  }
  return out;
}

void add_accuracy_json(Json& row, const std::optional<HorizontalAccuracy>& a) {
  const std::vector<std::string> keys = accuracy_header(LengthUnit::kMetre);
  for (std::size_t m = 0; m < kMetrics.size(); ++m) {
    const std::array<double, 3> v = a ? printed(*a, m, 1.0) : std::array<double, 3>{NAN, NAN, NAN};
    for (std::size_t p = 0; p < kParts.size(); ++p) row[keys[3 * m + p]] = std::isnan(v[p]) ? Json() : Json(v[p]);
  }
  row["quantile_samples"] = a ? Json(static_cast<double>(a->quantile_samples)) : Json();
}

}  // namespace insmc::mc
