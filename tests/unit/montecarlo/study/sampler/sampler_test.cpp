// Tests for montecarlo/study/sampler/sampler.h: every distribution kind stays in
// its support (fixed and zero exactly); draw() equals the bulk transform bit
// for bit; parameter j uses uniform j of its sample's stream; and the
// uniform and truncated-normal draws against their exact laws: the moment
// formulas of ParameterDistribution against numerical integration, then the
// draws' second and fourth moments and their Kolmogorov-Smirnov distance
// (statistical checks with power companions, header comment below).
#include "montecarlo/study/sampler/sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "lib/uncertainty/catalogue.h"

namespace insmc::mc {
namespace {

constexpr std::uint64_t kSeed = 20240601;

// All 33 parameters cycling through the four kinds: uniform, normal:3,
// fixed at ±0.7 bound (sign alternating), zero.
UncertaintyModel mixed_model() {
  UncertaintyModel m;
  for (int j = 0; j < uncertainty_slot::kDim; ++j) {
    ParameterDistribution& p = m.at(j);
    switch (j % 4) {
      case 0: p.kind = DistributionKind::kUniform; break;
      case 1:
        p.kind = DistributionKind::kTruncatedNormal;
        p.sigmas_in_bound = 3.0;
        break;
      case 2:
        p.kind = DistributionKind::kFixed;
        p.fixed_si = (j % 8 == 2 ? 0.7 : -0.7) * p.bound_si;
        break;
      default: p.kind = DistributionKind::kZero; break;
    }
  }
  return m;
}

// Sample-major uniforms of samples [first, first + n) and their transform.
std::vector<double> bulk_draws(const Sampler& s, std::uint64_t seed, std::uint64_t first, std::size_t n) {
  std::vector<double> u(n * uncertainty_slot::kDim), x(n * uncertainty_slot::kDim);
  fill_uniform01(seed, Stream::Uncertainties, first, uncertainty_slot::kDim, n, u);
  s.transform(u.data(), n, x.data());
  return x;
}

TEST(Sampler, EveryKindStaysInItsSupport) {
  const UncertaintyModel model = mixed_model();
  const Sampler sampler(model);
  constexpr std::size_t kN = 4096;
  const std::vector<double> x = bulk_draws(sampler, kSeed, 0, kN);
  for (std::size_t i = 0; i < kN; ++i) {
    for (int j = 0; j < uncertainty_slot::kDim; ++j) {
      const ParameterDistribution& p = model.at(j);
      const double v = x[i * uncertainty_slot::kDim + static_cast<std::size_t>(j)];
      switch (p.kind) {
        case DistributionKind::kUniform:
        case DistributionKind::kTruncatedNormal:
          ASSERT_LE(std::fabs(v), p.bound_si) << catalogue()[j].name << " sample " << i;
          break;
        case DistributionKind::kFixed: ASSERT_EQ(v, p.fixed_si) << catalogue()[j].name; break;
        case DistributionKind::kZero:
          ASSERT_EQ(v, 0.0) << catalogue()[j].name;
          ASSERT_FALSE(std::signbit(v)) << catalogue()[j].name;
          break;
      }
    }
  }
}

TEST(Sampler, ZeroBoundGivesZero) {
  UncertaintyModel model;
  model.at(0).bound_si = 0.0;  // uniform
  model.at(1).bound_si = 0.0;
  model.at(1).kind = DistributionKind::kTruncatedNormal;
  const Sampler sampler(model);
  for (std::uint64_t i = 0; i < 100; ++i) {
    const UncertaintyVector x = sampler.draw(kSeed, i);
    EXPECT_EQ(x[0], 0.0);
    EXPECT_EQ(x[1], 0.0);
  }
}

TEST(Sampler, DrawEqualsTheBulkTransformBitForBit) {
  const Sampler sampler(mixed_model());
  constexpr std::uint64_t kFirst = 3 * 1024 + 17;
  constexpr std::size_t kN = 300;
  const std::vector<double> bulk = bulk_draws(sampler, kSeed, kFirst, kN);
  for (std::size_t i = 0; i < kN; ++i) {
    const UncertaintyVector x = sampler.draw(kSeed, kFirst + i);
    for (int j = 0; j < uncertainty_slot::kDim; ++j) {
      ASSERT_EQ(x[j], bulk[i * uncertainty_slot::kDim + static_cast<std::size_t>(j)]) << "sample " << kFirst + i << " j " << j;
    }
  }
}

TEST(Sampler, TransformEqualsTransformOneBitForBit) {
  // transform() runs the uniform parameters through one vectorised pass
  // over runs of 4 samples and patches the other kinds afterwards; it must
  // equal transform_one entry by entry, sign of zero included, for every
  // sample count (whole runs and tails), with the extreme uniforms 0, 1/2
  // and 1 - 2^-53, and with zero and infinite uniform bounds.
  UncertaintyModel zero_and_inf;
  zero_and_inf.at(0).bound_si = 0.0;
  zero_and_inf.at(7).bound_si = std::numeric_limits<double>::infinity();
  zero_and_inf.at(9).kind = DistributionKind::kZero;
  for (const UncertaintyModel& model : {UncertaintyModel(), mixed_model(), zero_and_inf}) {
    const Sampler sampler(model);
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{4},
                                std::size_t{5}, std::size_t{9}, std::size_t{1024}, std::size_t{1027}}) {
      std::vector<double> u(n * uncertainty_slot::kDim), x(n * uncertainty_slot::kDim, -99.0);
      fill_uniform01(kSeed, Stream::Uncertainties, 11, uncertainty_slot::kDim, n, u);
      const double extremes[] = {0.0, 0.5, 1.0 - 0x1p-53};
      for (std::size_t i = 0; i < u.size(); i += 5) u[i] = extremes[(i / 5) % 3];
      sampler.transform(u.data(), n, x.data());
      std::vector<double> x_by_draw(n * uncertainty_slot::kDim, -99.0);  // the same uniforms read draw-major
      sampler.transform_draw_major(u.data(), n, x_by_draw.data());
      for (std::size_t s = 0; s < n; ++s) {
        for (int j = 0; j < uncertainty_slot::kDim; ++j) {
          const std::size_t i = s * uncertainty_slot::kDim + static_cast<std::size_t>(j);
          ASSERT_EQ(std::bit_cast<std::uint64_t>(x[i]),
                    std::bit_cast<std::uint64_t>(sampler.transform_one(j, u[i])))
              << "n " << n << " sample " << s << " j " << j << " u " << u[i];
          const std::size_t d = static_cast<std::size_t>(j) * n + s;
          ASSERT_EQ(std::bit_cast<std::uint64_t>(x_by_draw[d]),
                    std::bit_cast<std::uint64_t>(sampler.transform_one(j, u[d])))
              << "draw-major: n " << n << " sample " << s << " j " << j << " u " << u[d];
        }
      }
    }
  }
}

TEST(Sampler, ParameterJUsesUniformJOfItsSample) {
  // The reproducibility contract (sampler.h): x_j of sample i is a function
  // of uniform j of CounterStream(seed, Uncertainties, i) alone. For the
  // uniform kind the transform is (2u - 1) bound; for normal:K it is the
  // truncated-normal inverse CDF (u = 0 moved to 2^-54).
  UncertaintyModel model = mixed_model();
  const Sampler sampler(model);
  for (std::uint64_t i : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{1023}, std::uint64_t{1} << 40}) {
    CounterStream stream(kSeed, Stream::Uncertainties, i);
    const UncertaintyVector x = sampler.draw(kSeed, i);
    for (int j = 0; j < uncertainty_slot::kDim; ++j) {
      const double u = stream.uniform01();
      const ParameterDistribution& p = model.at(j);
      if (p.kind == DistributionKind::kUniform) {
        EXPECT_EQ(x[j], (2.0 * u - 1.0) * p.bound_si) << "j " << j;
      } else if (p.kind == DistributionKind::kTruncatedNormal) {
        const TruncatedNormalTransform t(p.bound_si / p.sigmas_in_bound, p.bound_si);
        EXPECT_EQ(x[j], t(std::max(u, 0x1p-54))) << "j " << j;
      }
    }
  }
  // Changing one parameter's distribution leaves every other draw unchanged.
  UncertaintyModel changed = model;
  changed.at(5).kind = DistributionKind::kUniform;
  changed.at(8).bound_si *= 2;
  const Sampler other(changed);
  for (std::uint64_t i = 0; i < 200; ++i) {
    const UncertaintyVector a = sampler.draw(kSeed, i), b = other.draw(kSeed, i);
    for (int j = 0; j < uncertainty_slot::kDim; ++j) {
      if (j == 5 || j == 8) continue;
      ASSERT_EQ(a[j], b[j]) << "sample " << i << " j " << j;
    }
  }
}

// ---------------------------------------------------------------- laws
//
// Statistics, for each continuous case below (uniform, normal:3, normal:1,
// normal:0.5), from n = kDraws draws of one parameter:
//  (1) mean of x^2 vs variance(): the mean of n i.i.d. x^2 is
//      asymptotically normal (CLT) with variance (m4 - m2^2)/n, m4 from
//      fourth_central_moment(); accept |mean - m2| <= z sqrt((m4 - m2^2)/n);
//  (2) mean of x^4 vs fourth_central_moment(): likewise, with the variance
//      (m8 - m4^2)/n, m8 by numerical integration of the density;
//  (3) the Kolmogorov-Smirnov distance D_n = sup |F_n - F| to the exact CDF:
//      by the Dvoretzky-Kiefer-Wolfowitz inequality with Massart's constant,
//      P(D_n > eps) <= 2 exp(-2 n eps^2) for every n (a finite-sample bound,
//      no asymptotics), so accept D_n <= sqrt(ln(2/a)/(2n)).
// Family-wise alpha 1e-6 over the 12 assertions (Bonferroni), a = alpha/12.
// Power companions: each statistic computed against the law with a 10%
// larger bound must fail. For (1), (2) the power is computed from the exact
// moments under the alternative (normal approximation); for (3) it is
// guaranteed by DKW: under the true law D_n(F_wrong) >= sup|F - F_wrong| -
// D_n(F), and D_n(F) <= eps_b with probability >= 1 - b; the test requires
// sup|F - F_wrong| - eps_b >= eps_a with b = 1e-3.

constexpr double kFamilyAlpha = 1e-6;
constexpr int kLawAssertions = 12;
constexpr double kAlpha = kFamilyAlpha / kLawAssertions;
constexpr double kPowerRequired = 0.999;
constexpr std::size_t kDraws = 100000;

struct LawCase {
  const char* name;
  DistributionKind kind;
  double sigmas_in_bound;  // for normal:K
};
constexpr LawCase kLawCases[] = {
    {"uniform", DistributionKind::kUniform, 0},
    {"normal:3", DistributionKind::kTruncatedNormal, 3.0},
    {"normal:1", DistributionKind::kTruncatedNormal, 1.0},
    {"normal:0.5", DistributionKind::kTruncatedNormal, 0.5},
};

// Independent references for a law with bound b: density and CDF on [-b, b].
double std_normal_cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

struct Law {
  DistributionKind kind;
  double bound, k;
  double pdf(double x) const {
    if (std::fabs(x) > bound) return 0.0;
    if (kind == DistributionKind::kUniform) return 0.5 / bound;
    const double sigma = bound / k, z = x / sigma;
    const double mass = std_normal_cdf(k) - std_normal_cdf(-k);
    return std::exp(-0.5 * z * z) / (sigma * std::sqrt(2 * std::numbers::pi) * mass);
  }
  double cdf(double x) const {
    if (x <= -bound) return 0.0;
    if (x >= bound) return 1.0;
    if (kind == DistributionKind::kUniform) return (x + bound) / (2 * bound);
    const double sigma = bound / k;
    return (std_normal_cdf(x / sigma) - std_normal_cdf(-k)) / (std_normal_cdf(k) - std_normal_cdf(-k));
  }
  // E[x^p] by composite Simpson on [-b, b] (smooth integrand, 4000 panels:
  // error ~ h^4 f'''' relative ~1e-14).
  double moment(int p) const {
    constexpr int kPanels = 4000;
    const double h = 2 * bound / kPanels;
    double s = 0;
    for (int i = 0; i <= kPanels; ++i) {
      const double x = -bound + i * h;
      const double w = (i == 0 || i == kPanels) ? 1 : (i % 2 ? 4 : 2);
      s += w * std::pow(x, p) * pdf(x);
    }
    return s * h / 3;
  }
};

// Draws of parameter `j` with the case's law, in blocks as the engine does.
std::vector<double> draws_of(const LawCase& c, int j, std::size_t n) {
  UncertaintyModel model;
  for (int i = 0; i < uncertainty_slot::kDim; ++i) model.at(i).kind = DistributionKind::kZero;
  model.at(j).kind = c.kind;
  if (c.kind == DistributionKind::kTruncatedNormal) model.at(j).sigmas_in_bound = c.sigmas_in_bound;
  const Sampler sampler(model);
  std::vector<double> out;
  out.reserve(n);
  constexpr std::size_t kChunk = 1024;
  for (std::size_t first = 0; first < n; first += kChunk) {
    const std::size_t m = std::min(kChunk, n - first);
    const std::vector<double> x = bulk_draws(sampler, kSeed + static_cast<std::uint64_t>(j), first, m);
    for (std::size_t i = 0; i < m; ++i) out.push_back(x[i * uncertainty_slot::kDim + static_cast<std::size_t>(j)]);
  }
  return out;
}

double ks_distance(std::vector<double> x, const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    d = std::max({d, static_cast<double>(i + 1) / n - f, f - static_cast<double>(i) / n});
  }
  return d;
}

double dkw_epsilon(std::size_t n, double alpha) {
  return std::sqrt(std::log(2 / alpha) / (2 * static_cast<double>(n)));
}

// Two-sided z test power: the statistic is N(shift, sd_alt^2), the test
// rejects outside +-z sd_null.
double two_sided_power(double shift, double sd_null, double sd_alt, double z) {
  const boost::math::normal nd;
  return boost::math::cdf(nd, (-z * sd_null - shift) / sd_alt) +
         boost::math::cdf(boost::math::complement(nd, (z * sd_null - shift) / sd_alt));
}

TEST(SamplerLaw, MomentFormulasMatchNumericalIntegration) {
  constexpr double kIntegrationTol = 1e-10;  // relative; Simpson with 4000 panels
  for (const LawCase& c : kLawCases) {
    ParameterDistribution p;
    p.kind = c.kind;
    p.bound_si = 2.5e-3;
    p.sigmas_in_bound = c.sigmas_in_bound > 0 ? c.sigmas_in_bound : 3.0;
    const Law law{c.kind, p.bound_si, p.sigmas_in_bound};
    EXPECT_NEAR(law.moment(0), 1.0, kIntegrationTol) << c.name;
    EXPECT_NEAR(p.variance(), law.moment(2), kIntegrationTol * law.moment(2)) << c.name;
    EXPECT_NEAR(p.fourth_central_moment(), law.moment(4), kIntegrationTol * law.moment(4)) << c.name;
    EXPECT_EQ(p.mean(), 0.0) << c.name;
  }
  // Fixed and zero: a point mass.
  ParameterDistribution fixed;
  fixed.kind = DistributionKind::kFixed;
  fixed.fixed_si = -4.0;
  EXPECT_EQ(fixed.mean(), -4.0);
  EXPECT_EQ(fixed.variance(), 0.0);
  EXPECT_EQ(fixed.fourth_central_moment(), 0.0);
}

TEST(SamplerLaw, DrawsFollowTheExactLaw) {
  const double z = boost::math::quantile(boost::math::complement(boost::math::normal(), kAlpha / 2));
  const double eps_a = dkw_epsilon(kDraws, kAlpha);
  const double eps_b = dkw_epsilon(kDraws, 1 - kPowerRequired);
  const double n = static_cast<double>(kDraws);
  int j = 0;
  for (const LawCase& c : kLawCases) {
    j = (j + 7) % uncertainty_slot::kDim;  // a different parameter (and bound) per case
    const std::vector<double> x = draws_of(c, j, kDraws);
    UncertaintyModel model;
    model.at(j).kind = c.kind;
    if (c.kind == DistributionKind::kTruncatedNormal) model.at(j).sigmas_in_bound = c.sigmas_in_bound;
    const ParameterDistribution& p = model.at(j);
    const Law law{c.kind, p.bound_si, p.sigmas_in_bound};
    const Law wrong{c.kind, 1.1 * p.bound_si, p.sigmas_in_bound};  // the power companion's law
    double s2 = 0, s4 = 0;
    for (const double v : x) {
      s2 += v * v;
      s4 += v * v * v * v;
    }
    const double mean2 = s2 / n, mean4 = s4 / n;
    const double m2 = p.variance(), m4 = p.fourth_central_moment(), m8 = law.moment(8);
    const double sd2 = std::sqrt((m4 - m2 * m2) / n), sd4 = std::sqrt((m8 - m4 * m4) / n);

    // (1), (2): the moments.
    EXPECT_LE(std::fabs(mean2 - m2), z * sd2) << c.name << ": mean x^2 " << mean2 << " vs " << m2;
    EXPECT_LE(std::fabs(mean4 - m4), z * sd4) << c.name << ": mean x^4 " << mean4 << " vs " << m4;
    // (3): KS against the exact CDF.
    const double d = ks_distance(x, [&](double v) { return law.cdf(v); });
    EXPECT_LE(d, eps_a) << c.name << ": KS distance";
    std::cout << c.name << ": z(x^2) = " << (mean2 - m2) / sd2 << ", z(x^4) = " << (mean4 - m4) / sd4
              << ", D_n = " << d << " (accept <= " << eps_a << ")\n";

    // Power companions: the same checks against the law with bound x 1.1.
    const double w2 = wrong.moment(2), w4 = wrong.moment(4), w8 = wrong.moment(8);
    const double wsd2 = std::sqrt((w4 - w2 * w2) / n), wsd4 = std::sqrt((w8 - w4 * w4) / n);
    // True mean2 ~ N(m2, sd2^2); the check against w2 rejects outside +-z wsd2.
    const double power2 = two_sided_power(m2 - w2, wsd2, sd2, z);
    const double power4 = two_sided_power(m4 - w4, wsd4, sd4, z);
    double sup_diff = 0;  // sup |F - F_wrong|, on a fine grid (both are monotone)
    for (int i = 0; i <= 20000; ++i) {
      const double v = wrong.bound * (-1 + i / 10000.0);
      sup_diff = std::max(sup_diff, std::fabs(law.cdf(v) - wrong.cdf(v)));
    }
    ASSERT_GE(power2, kPowerRequired) << c.name;
    ASSERT_GE(power4, kPowerRequired) << c.name;
    ASSERT_GE(sup_diff - eps_b, eps_a) << c.name << ": KS power not guaranteed";
    EXPECT_GT(std::fabs(mean2 - w2), z * wsd2) << c.name << ": x^2 check cannot see a 10% wider bound";
    EXPECT_GT(std::fabs(mean4 - w4), z * wsd4) << c.name << ": x^4 check cannot see a 10% wider bound";
    EXPECT_GT(ks_distance(x, [&](double v) { return wrong.cdf(v); }), eps_a)
        << c.name << ": KS check cannot see a 10% wider bound";
  }
}

}  // namespace
}  // namespace insmc::mc
