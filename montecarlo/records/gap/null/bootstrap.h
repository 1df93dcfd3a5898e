#pragma once
/// Null files and their statistics: a null file is a resample with
/// replacement of the null runs, as many as the records have, and the
/// records' p-values and critical values are read against those files.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace insmc::gap {

/// 0, 1, ..., n − 1: every run once.
std::vector<int> all_runs(std::size_t n);

/// Indices of a resample with replacement of `n` out of `pool` (stream index b).
std::vector<int> resample(std::uint64_t seed, std::uint64_t b, int n, int pool);

/// The q quantile of `v`, linear between order statistics (0 when empty).
double quantile(std::vector<double> v, double q);

/// The share of null values at least `observed`, with the observed counted
/// among them (never 0).
double p_value_of(double observed, const std::vector<double>& null);

/// The value a statistic must exceed for p_value_of to be at most alpha: the
/// (k+1)-th largest null value, k = ⌊alpha (n + 1)⌋ − 1, so that "beyond the
/// critical value" and "p ≤ alpha" are one decision (a quantile 1 − alpha
/// between order statistics let a value beyond it keep p = 0.0105 at alpha
/// 0.01). +∞ when no p can reach alpha, the least null value when every
/// one does.
double critical_value(std::vector<double> null, double alpha);

}  // namespace insmc::gap
