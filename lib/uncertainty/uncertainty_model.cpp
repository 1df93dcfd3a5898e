#include "lib/uncertainty/uncertainty_model.h"

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <numbers>

#include "lib/common/input_error.h"

namespace insmc {
namespace {

double normal_pdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2 * std::numbers::pi); }
double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

/// Moments of a standard normal truncated to [−k, k]: E[z²] and E[z⁴].
std::pair<double, double> truncated_normal_moments(double k) {
  const double z = 2 * normal_cdf(k) - 1;
  const double m2 = 1 - 2 * k * normal_pdf(k) / z;
  const double m4 = 3 * m2 - 2 * k * k * k * normal_pdf(k) / z;  // by parts: E z⁴ = 3E z² − 2k³φ(k)/Z
  return {m2, m4};
}

std::string names_accepted() {
  return fmt::format("a catalogue name (insmc params), a group ({}) or all",
                     fmt::join(uncertainty_groups(), ", "));
}

}  // namespace

double ParameterDistribution::mean() const {
  return kind == DistributionKind::kFixed ? fixed_si : 0.0;
}

double ParameterDistribution::variance() const {
  switch (kind) {
    case DistributionKind::kUniform: return bound_si * bound_si / 3.0;
    case DistributionKind::kTruncatedNormal: {
      const double sigma = bound_si / sigmas_in_bound;
      return sigma * sigma * truncated_normal_moments(sigmas_in_bound).first;
    }
    case DistributionKind::kFixed:
    case DistributionKind::kZero: return 0.0;
  }
  return 0.0;
}

double ParameterDistribution::fourth_central_moment() const {
  switch (kind) {
    case DistributionKind::kUniform: return std::pow(bound_si, 4) / 5.0;
    case DistributionKind::kTruncatedNormal: {
      const double sigma = bound_si / sigmas_in_bound;
      return std::pow(sigma, 4) * truncated_normal_moments(sigmas_in_bound).second;
    }
    case DistributionKind::kFixed:
    case DistributionKind::kZero: return 0.0;
  }
  return 0.0;
}

std::string ParameterDistribution::describe() const {
  switch (kind) {
    case DistributionKind::kUniform: return "uniform";
    case DistributionKind::kTruncatedNormal: return fmt::format("normal:{}", sigmas_in_bound);
    case DistributionKind::kFixed: return "fixed";
    case DistributionKind::kZero: return "zero";
  }
  return "?";
}

UncertaintyModel::UncertaintyModel() {
  for (const auto& spec : catalogue()) params_[spec.index].bound_si = spec.default_bound_si;
}

std::pair<std::vector<int>, std::string> split_assignment(std::string_view a, std::string_view option) {
  const auto eq = a.find('=');
  if (eq == std::string_view::npos || eq == 0 || eq + 1 == a.size())
    throw InputError(std::string(option), std::string(a), "expected NAME=VALUE with NAME " + names_accepted());
  const std::string name(a.substr(0, eq));
  std::vector<int> idx = select_uncertainties(name);
  if (idx.empty())
    throw InputError(std::string(option), std::string(a), "unknown name '" + name + "'; expected " + names_accepted());
  return {idx, std::string(a.substr(eq + 1))};
}

void UncertaintyModel::apply_bound(std::string_view assignment) {
  const auto [indices, list] = split_assignment(assignment, "--bound");
  const std::string value = list.substr(0, list.find(','));  // a comma list is a sweep: its first value
  for (int i : indices) {
    const UncertaintySpec& spec = catalogue()[i];
    const std::string field = fmt::format("--bound {}", spec.name);
    const double b = parse_quantity(value, spec.dimension, field);
    require_in_range(field, b, spec.dimension, bound_range(spec));
    params_[i].bound_si = b;
  }
}

void UncertaintyModel::apply_dist(std::string_view assignment) {
  const auto [indices, spec_text] = split_assignment(assignment, "--dist");
  const std::string allowed = "must be uniform, normal:K (bound = K sigma, K > 0), fixed:VALUE (with unit) or zero";
  for (int i : indices) {
    const UncertaintySpec& spec = catalogue()[i];
    const std::string field = fmt::format("--dist {}", spec.name);
    ParameterDistribution& p = params_[i];
    if (spec_text == "uniform") {
      p.kind = DistributionKind::kUniform;
    } else if (spec_text == "zero") {
      p.kind = DistributionKind::kZero;
    } else if (spec_text.rfind("normal:", 0) == 0) {
      const double k = parse_quantity(spec_text.substr(7), Dimension::kDimensionless, field);
      // K beyond 100 is a point mass at the mean in all but name; below 0.1
      // the truncated normal is a uniform in all but name.
      require_in_range(field + " K", k, Dimension::kDimensionless, {0.1, 100.0});
      p.kind = DistributionKind::kTruncatedNormal;
      p.sigmas_in_bound = k;
    } else if (spec_text.rfind("fixed:", 0) == 0) {
      p.kind = DistributionKind::kFixed;
      p.fixed_si = parse_quantity(spec_text.substr(6), spec.dimension, field);
      const PhysicalRange range = bound_range(spec);
      require_in_range(field, p.fixed_si, spec.dimension, {-range.max_si, range.max_si});
    } else {
      throw InputError(field, spec_text, allowed);
    }
  }
}

UncertaintyVector UncertaintyModel::mean() const {
  UncertaintyVector v;
  for (int i = 0; i < uncertainty_slot::kDim; ++i) v[i] = params_[i].mean();
  return v;
}

UncertaintyVector UncertaintyModel::variance() const {
  UncertaintyVector v;
  for (int i = 0; i < uncertainty_slot::kDim; ++i) v[i] = params_[i].variance();
  return v;
}

UncertaintyVector UncertaintyModel::fourth_central_moment() const {
  UncertaintyVector v;
  for (int i = 0; i < uncertainty_slot::kDim; ++i) v[i] = params_[i].fourth_central_moment();
  return v;
}

}  // namespace insmc
