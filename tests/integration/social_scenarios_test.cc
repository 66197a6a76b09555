// The named interaction scenarios: every scenario starts everybody in free space, apart, for any
// count up to its most and many seeds; a seed gives one scenario, another seed another; too many
// people is a clear error.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

const std::vector<std::string> kScenarios = {
    "frontal_approach", "overtaking",   "crossing",        "doorway",    "narrow_hallway",
    "blind_corner",     "intersection", "standing_person", "join_group", "leave_group"};

class SocialScenariosTest : public ::testing::TestWithParam<std::string> {
 protected:
  std::shared_ptr<WorldSource> World() {
    const auto& plugin = registry_.Load("social_scenarios", PluginKind::kWorld);
    Params p = Params::Defaults(plugin.schema);
    p.Set("scenario", GetParam());
    return registry_.MakeWorld(plugin, p);
  }
  static ScenarioRequest Request(std::uint64_t seed, int people) {
    ScenarioRequest r;
    r.seed = seed;
    r.num_humans = people;
    return r;
  }
  PluginRegistry registry_{{testing::PluginDir()}};
};

TEST_P(SocialScenariosTest, EverybodyStartsInFreeSpaceApart) {
  const auto world = World();
  EXPECT_EQ(world->Identity(), "social_scenarios:scenario=" + GetParam());
  for (int people = 0; people <= 6; ++people) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
      const Scenario s = world->Make(Request(seed, people));
      ASSERT_EQ(static_cast<int>(s.humans.size()), people);
      EXPECT_EQ(s.layout, GetParam());
      EXPECT_NO_THROW(CheckScenario(s, SimConfig{})) << GetParam() << " seed " << seed;
      for (size_t i = 0; i < s.humans.size(); ++i) {
        EXPECT_GT((s.humans[i].start - s.robot_start).norm(), 1.0);
        EXPECT_TRUE(s.map->bounds.Contains(s.humans[i].goals.front()));
        for (size_t j = 0; j < i; ++j) {
          EXPECT_GT((s.humans[i].start - s.humans[j].start).norm(), 0.6 + 0.2)
              << GetParam() << " seed " << seed << " people " << i << ", " << j;
        }
      }
    }
  }
}

TEST_P(SocialScenariosTest, ASeedGivesOneScenarioAndAnotherSeedAnother) {
  const auto world = World();
  const Scenario a = world->Make(Request(7, 3)), b = world->Make(Request(7, 3));
  const Scenario c = world->Make(Request(8, 3));
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.humans[i].start, b.humans[i].start);
    EXPECT_EQ(a.humans[i].v_pref, b.humans[i].v_pref);
  }
  EXPECT_NE(a.humans[0].start, c.humans[0].start);
}

TEST_P(SocialScenariosTest, MorePeopleThanTheGeometryHoldsIsAClearError) {
  try {
    World()->Make(Request(1, 7));
    FAIL() << "7 people were placed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("places at most 6 people, asked for 7"), std::string::npos)
        << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Scenarios, SocialScenariosTest, ::testing::ValuesIn(kScenarios));

// The group scenarios: everybody stands in one conversational group whose open place is the
// robot's goal (join) or start (leave): members on a circle around a centre beyond that place,
// the open place as far out as they are, no member nearer to it than 1 m (an F-formation's
// gap the robot fits in).
TEST(SocialGroupScenarios, PeopleStandInACircleWithTheRobotsPlaceOpen) {
  PluginRegistry registry{{testing::PluginDir()}};
  const auto& plugin = registry.Load("social_scenarios", PluginKind::kWorld);
  for (const std::string name : {"join_group", "leave_group"}) {
    Params p = Params::Defaults(plugin.schema);
    p.Set("scenario", name);
    const auto world = registry.MakeWorld(plugin, p);
    for (int people = 2; people <= 6; ++people) {
      for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        ScenarioRequest r;
        r.seed = seed;
        r.num_humans = people;
        const Scenario s = world->Make(r);
        const Vec2 place = name == "join_group" ? s.robot_goal : s.robot_start;
        Vec2 centre = Vec2::Zero();
        for (const HumanSpec& h : s.humans) centre += h.start;
        centre /= people;
        for (const HumanSpec& h : s.humans) {
          EXPECT_EQ(h.group, 0);
          EXPECT_EQ(h.goals.front(), h.start);  // they stand
          EXPECT_GE((h.start - place).norm(), 1.0) << name << " seed " << seed;
          EXPECT_GT(h.start.x(), place.x());  // the group lies beyond the robot's place
        }
      }
    }
  }
}

}  // namespace
}  // namespace crowdsim
