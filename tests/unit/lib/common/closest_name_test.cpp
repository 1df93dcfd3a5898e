// "Did you mean" (lib/common/closest_name.h): a slip gets the name meant,
// a different word gets none.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/common/closest_name.h"

namespace insmc {
namespace {

const std::vector<std::string> kOptions = {"--records", "--samples", "--seed", "--scheme", "--system", "--out"};

TEST(ClosestName, ATransposedOrMissingLetterFindsTheName) {
  EXPECT_EQ(closest_name("--recrods", kOptions), "--records");
  EXPECT_EQ(closest_name("--smaples", kOptions), "--samples");
  EXPECT_EQ(closest_name("--seeed", kOptions), "--seed");
  EXPECT_EQ(closest_name("--schem", kOptions), "--scheme");
}

TEST(ClosestName, AnUnrelatedWordOrAnExactNameGetsNoSuggestion) {
  EXPECT_FALSE(closest_name("--gyro-drift-bound", kOptions));
  EXPECT_FALSE(closest_name("--records", kOptions));
  EXPECT_FALSE(closest_name("", kOptions));
  EXPECT_FALSE(closest_name(std::string(100000, 'x'), kOptions));
}

TEST(ClosestName, TheSuggestionReadsInTheMessage) {
  EXPECT_EQ(did_you_mean("--recrods", kOptions), " (did you mean --records?)");
  EXPECT_EQ(did_you_mean("--zzzzzzzz", kOptions), "");
}

}  // namespace
}  // namespace insmc
