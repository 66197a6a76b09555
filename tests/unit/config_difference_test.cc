// DescribeConfigDifference: what an error message says differs between two canonical
// configuration texts (a training's resume against the one it started with).
#include <gtest/gtest.h>

#include <string>

#include "spec/config_text.h"

namespace crowdsim::suite_internal {
namespace {

TEST(ConfigDifference, NamesTheParameterOfThePluginUseThatChanged) {
  // Two plugin uses on one line: the lidar's max_range, not the person sensor's.
  EXPECT_EQ(
      DescribeConfigDifference("sensors:person{max_range=0;}lidar2d{beams=45;max_range=5;}\n",
                               "sensors:person{max_range=0;}lidar2d{beams=45;max_range=6;}\n"),
      "sensors: lidar2d max_range 5 -> 6");
  EXPECT_EQ(DescribeConfigDifference("humans:5-5,orca{a=1;}\nseed=7\n",
                                     "humans:3-3,orca{a=1;}\nseed=8\n"),
            "humans: 5-5,orca -> 3-3,orca; seed: 7 -> 8");
  EXPECT_EQ(DescribeConfigDifference("policy:cadrl{speed_samples=5;}\n", "policy:cadrl{}\n"),
            "policy: speed_samples (gone)");
}

TEST(ConfigDifference, ShowsALongValueFromJustBeforeItsFirstDifference) {
  const std::string a =
      "training:3000,50,0.01,10000,0.001,0.9,0.5,0.1,4000,50,100000,100,100,1000,100\n";
  std::string b = a;
  b.replace(b.find("0.5,0.1"), 7, "0.5,0.2");
  const std::string d = DescribeConfigDifference(a, b);
  EXPECT_NE(d.find("0.5,0.1,4000"), std::string::npos) << d;
  EXPECT_NE(d.find("-> ..."), std::string::npos) << d;
  EXPECT_NE(d.find("0.5,0.2,4000"), std::string::npos) << d;
}

TEST(ConfigDifference, DataFilesAndRemovedUsesAndCommentsAndEqualTexts) {
  const std::string d =
      DescribeConfigDifference("world:floorplan{data:worlds/x.yaml#content:aaaa;}\n",
                               "world:floorplan{data:worlds/x.yaml#content:bbbb;}\n");
  EXPECT_NE(d.find("world: data:worlds/x.yaml"), std::string::npos) << d;
  EXPECT_NE(d.find("#content:aaaa -> "), std::string::npos) << d;
  EXPECT_NE(DescribeConfigDifference("sensors:person{}lidar2d{beams=45;}\n", "sensors:person{}\n")
                .find("sensors: person{}lidar2d{beams=45;} -> person{}"),
            std::string::npos);
  EXPECT_EQ(DescribeConfigDifference("# copy of a.yaml\nseed=1\n", "# copy of b.yaml\nseed=1\n"),
            "");
  EXPECT_EQ(DescribeConfigDifference("seed=1\n", "seed=1\nextra:x\n"), "extra: new");
  EXPECT_EQ(DescribeConfigDifference("policy:cadrl{a=1;}\n", "policy:cadrl{a=1;b=2;}\n"),
            "policy: b=2 (new)");
}

TEST(ConfigDifference, APositionalLineIsNamedValueByValue) {
  // A training's "training:" line: the values that changed, by name, not both lines' digits.
  const std::map<std::string, std::vector<std::string>> names = {
      {"training", {"il_episodes", "il_epochs", "rl_episodes"}}};
  EXPECT_EQ(DescribeConfigDifference("training:3000,50,10000,store_timeouts=off\n",
                                     "training:3000,40,10000,store_timeouts=terminal\n", names),
            "training: il_epochs 50 -> 40, store_timeouts off -> terminal");
  EXPECT_EQ(DescribeConfigDifference("training:1,2,3\n", "training:1,2,3,exploration=x\n", names),
            "training: exploration=x (new)");
  EXPECT_EQ(DescribeConfigDifference("training:1,2\n", "training:1,2,3\n", names),
            "training: rl_episodes=3 (new)");
  EXPECT_NO_THROW(DescribeConfigDifference("training:1,2,3,4\n", "training:\n", names));
}

TEST(ConfigDifference, OddLinesOfAHandEditedFileDoNotThrow) {
  // A line that is its key alone against one with a separator; braces left open or reversed.
  const char* texts[] = {"ab", "ab:x", "ab={", "a;x", "a;x={", "k:{", "k:}{", "k:a{b=1", "", "\n"};
  for (const char* a : texts) {
    for (const char* b : texts) {
      EXPECT_NO_THROW(DescribeConfigDifference(a, b)) << "'" << a << "' vs '" << b << "'";
    }
  }
  EXPECT_EQ(DescribeConfigDifference("ab\n", "ab:x\n"), "ab:  -> x");
}

}  // namespace
}  // namespace crowdsim::suite_internal
