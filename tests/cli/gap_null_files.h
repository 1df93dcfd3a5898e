#pragma once
// What the null-file tests of the diagnosis share: how many files to run
// (an environment variable for the long measurement), the binomial bound of
// false alarms at a level, and reading a finding out of `gap --format json`.
#include <boost/math/distributions/binomial.hpp>
#include <gtest/gtest.h>

#include <algorithm>
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
  const boost::math::binomial_distribution<double> files(n, p);
  int k = 0;
  while (k < n && boost::math::cdf(boost::math::complement(files, k)) >= 1e-3) ++k;
  return k;
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
