#include "crowdsim/bench/closest_name.h"

#include <gtest/gtest.h>

namespace crowdsim {
namespace {

const std::vector<std::string> kSuiteKeys = {"name",  "description", "seed",  "sim",     "episodes",
                                             "world", "humans",      "robot", "columns", "rows"};

TEST(ClosestName, OneLetterMissingExtraWrongOrSwapped) {
  EXPECT_EQ(ClosestName("episode", kSuiteKeys), "episodes");
  EXPECT_EQ(ClosestName("episodess", kSuiteKeys), "episodes");
  EXPECT_EQ(ClosestName("epizodes", kSuiteKeys), "episodes");
  EXPECT_EQ(ClosestName("epsiodes", kSuiteKeys), "episodes");
  EXPECT_EQ(ClosestName("Humans", kSuiteKeys), "humans");  // case ignored
  EXPECT_EQ(ClosestName("descripton", kSuiteKeys), "description");
}

TEST(ClosestName, NothingWhenFarTiedExactOrTooShort) {
  EXPECT_EQ(ClosestName("rl_episodes", kSuiteKeys), std::nullopt);  // 3 edits from episodes
  EXPECT_EQ(ClosestName("timing", kSuiteKeys), std::nullopt);
  EXPECT_EQ(ClosestName("abc", {"abd", "abe"}), std::nullopt);  // two as near
  EXPECT_EQ(ClosestName("seed", kSuiteKeys), std::nullopt);     // valid as it is
  EXPECT_EQ(ClosestName("se", {"sed"}), std::nullopt);          // under three letters
  EXPECT_EQ(ClosestName("robt", kSuiteKeys), "robot");          // short names: one edit
  EXPECT_EQ(ClosestName("rbt", kSuiteKeys), std::nullopt);      // two
  EXPECT_EQ(ClosestName("anything", {}), std::nullopt);
}

TEST(ClosestName, DidYouMeanIsTheMessagesTail) {
  EXPECT_EQ(DidYouMean("episode", kSuiteKeys), "; did you mean 'episodes'?");
  EXPECT_EQ(DidYouMean("rl_episodes", kSuiteKeys), "");
}

}  // namespace
}  // namespace crowdsim
