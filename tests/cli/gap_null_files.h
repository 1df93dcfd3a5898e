#pragma once
// What the null-file tests of the diagnosis share: how many files to run
// (an environment variable for the long measurement), the binomial bound of
// false alarms at a level, and reading a finding out of `gap --format json`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace insmc::testing {

/// The number of files in `variable`, else `fallback` (CI).
inline int null_files_from_env(const char* variable, int fallback) {
  const char* v = std::getenv(variable);
  return v ? std::clamp(std::atoi(v), 1, 10000) : fallback;
}

/// Least k with P(X > k) < 1e-3 for X ~ Binomial(n, p): the most false
/// alarms a test of level p leaves in n files at that confidence.
inline int binomial_bound(int n, double p) {
  double cdf = 0.0;
  for (int k = 0; k <= n; ++k) {
    cdf += std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) + k * std::log(p) +
                    (n - k) * std::log1p(-p));
    if (1.0 - cdf < 1e-3) return k;
  }
  return n;
}

/// The JSON object that follows `"key": ` (up to its first closing brace).
inline std::string object_after(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": {");
  if (at == std::string::npos) return {};
  return json.substr(at, json.find('}', at) - at + 1);
}

/// The value of "significant" in the object that follows `key` in the JSON text.
inline bool significant_after(const std::string& json, const std::string& key) {
  const std::string object = object_after(json, key);
  EXPECT_FALSE(object.empty()) << key;
  return object.find("\"significant\": true") != std::string::npos;
}

}  // namespace insmc::testing
