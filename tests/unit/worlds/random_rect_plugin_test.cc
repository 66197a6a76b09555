// The random_rect world plugin, loaded as a suite would load it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <thread>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/human_placement.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;

class RandomRectPlugin : public ::testing::Test {
 protected:
  std::shared_ptr<WorldSource> Make(std::map<std::string, ParamValue> values) {
    const LoadedPlugin& p = registry_.Load("random_rect", PluginKind::kWorld);
    Params params = Params::Defaults(p.schema);
    for (auto& [k, v] : values) params.Set(k, v);
    return registry_.MakeWorld(p, params);
  }
  PluginRegistry registry_{{crowdsim::testing::PluginDir()}};
};

ScenarioRequest Request(std::uint64_t seed, std::int64_t episode, int humans = 5,
                        HumanGoalMode mode = HumanGoalMode::kStay) {
  ScenarioRequest r;
  r.seed = seed;
  r.episode_index = episode;
  r.num_humans = humans;
  r.goal_mode = mode;
  return r;
}

bool Same(const Scenario& a, const Scenario& b) {
  if (a.map != b.map || a.robot_start != b.robot_start || a.robot_goal != b.robot_goal ||
      a.seed != b.seed || a.layout != b.layout || a.humans.size() != b.humans.size()) {
    return false;
  }
  for (size_t i = 0; i < a.humans.size(); ++i) {
    if (a.humans[i].start != b.humans[i].start || a.humans[i].goals != b.humans[i].goals ||
        a.humans[i].radius != b.humans[i].radius || a.humans[i].v_pref != b.humans[i].v_pref) {
      return false;
    }
  }
  return true;
}

TEST_F(RandomRectPlugin, LoadsTheFrozenSetsWithAStableIdentity) {
  const auto one = Make({});
  EXPECT_EQ(one->Identity(), "random_rect:obstacles=1:split=test");
  EXPECT_EQ(one->LayoutCount(), 100);
  const auto three = Make({{"obstacles", std::int64_t{3}}, {"split", std::string("train")}});
  EXPECT_EQ(three->Identity(), "random_rect:obstacles=3:split=train");
  EXPECT_EQ(three->LayoutCount(), 100);
  EXPECT_EQ(three->Make(Request(1, 17)).layout, "rect3_train_017");
  const auto tweaked = Make({{"min_start_goal_dist", 5.0}});
  EXPECT_EQ(tweaked->Identity(), "random_rect:obstacles=1:split=test:min_start_goal_dist=5");
}

TEST_F(RandomRectPlugin, SameRequestSameScenarioOtherSeedOtherScenario) {
  const auto world = Make({{"obstacles", std::int64_t{3}}});
  const Scenario a = world->Make(Request(123, 4));
  const Scenario b = world->Make(Request(123, 4));
  const Scenario c = world->Make(Request(124, 4));
  EXPECT_TRUE(Same(a, b));
  EXPECT_FALSE(Same(a, c));
  EXPECT_EQ(a.map, c.map) << "same layout, same cached map";
  EXPECT_NE(a.robot_start, c.robot_start);
  EXPECT_EQ(a.seed, 123u);
}

TEST_F(RandomRectPlugin, LayoutsCycleAndMapsAreSharedPerLayout) {
  const auto world = Make({{"obstacles", std::int64_t{3}}});
  const Scenario e0 = world->Make(Request(1, 0));
  const Scenario e1 = world->Make(Request(1, 1));
  const Scenario e100 = world->Make(Request(2, 100));
  EXPECT_EQ(e0.map.get(), e100.map.get());
  EXPECT_NE(e0.map.get(), e1.map.get());
  EXPECT_EQ(e0.layout, "rect3_test_000");
  EXPECT_EQ(e1.layout, "rect3_test_001");
  EXPECT_EQ(e0.map->rectangles.size(), 7u);
}

TEST_F(RandomRectPlugin, RobotAndHumansFollowThePlacementRules) {
  for (std::int64_t obstacles : {0, 1, 3}) {
    const auto world = Make({{"obstacles", obstacles}});
    for (std::int64_t ep = 0; ep < 40; ++ep) {
      const Scenario s = world->Make(Request(DeriveSeed(7, world->Identity(), ep), ep));
      const DiscFreeSpace space(s.map, 0.3 + 0.1);
      EXPECT_TRUE(space.Contains(s.robot_start));
      EXPECT_TRUE(space.Contains(s.robot_goal));
      EXPECT_GE((s.robot_goal - s.robot_start).norm(), 7.0);
      ASSERT_EQ(s.humans.size(), 5u);
      for (size_t i = 0; i < s.humans.size(); ++i) {
        const HumanSpec& h = s.humans[i];
        ASSERT_EQ(h.goals.size(), 1u);
        EXPECT_TRUE(space.Contains(h.start));
        EXPECT_TRUE(space.Contains(h.goals[0]));
        EXPECT_GE((h.start - s.robot_start).norm(), 0.8);
        EXPECT_GE((h.goals[0] - s.robot_goal).norm(), 0.8);
        EXPECT_GE((h.goals[0] - h.start).norm(), 3.0);
        for (size_t j = 0; j < i; ++j) {
          EXPECT_GE((h.start - s.humans[j].start).norm(), 0.8);
          EXPECT_GE((h.goals[0] - s.humans[j].goals[0]).norm(), 0.8);
        }
      }
    }
  }
}

TEST_F(RandomRectPlugin, NewGoalModeGivesSixteenGoals) {
  const auto world = Make({{"obstacles", std::int64_t{1}}});
  const Scenario s = world->Make(Request(5, 3, 5, HumanGoalMode::kNewGoal));
  for (const HumanSpec& h : s.humans) EXPECT_EQ(h.goals.size(), 16u);
}

TEST_F(RandomRectPlugin, EmptyRoomNeedsNoFile) {
  const auto world = Make({{"obstacles", std::int64_t{0}}});
  EXPECT_EQ(world->LayoutCount(), 1);
  EXPECT_EQ(world->Identity(), "random_rect:obstacles=0:split=test");
  const Scenario s = world->Make(Request(1, 9));
  EXPECT_EQ(s.map->rectangles.size(), 4u);
  EXPECT_EQ(s.map->bounds, Rect::FromCorners(-5.5, -5.5, 5.5, 5.5));
}

TEST_F(RandomRectPlugin, MakeIsThreadSafe) {
  const auto world = Make({{"obstacles", std::int64_t{3}}});
  constexpr int kEpisodes = 64;
  std::vector<Scenario> serial, parallel(kEpisodes);
  for (int ep = 0; ep < kEpisodes; ++ep) serial.push_back(world->Make(Request(900 + ep, ep)));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int ep = t; ep < kEpisodes; ep += 4) parallel[ep] = world->Make(Request(900 + ep, ep));
    });
  }
  for (auto& th : threads) th.join();
  for (int ep = 0; ep < kEpisodes; ++ep) EXPECT_TRUE(Same(serial[ep], parallel[ep])) << ep;
}

TEST_F(RandomRectPlugin, MissingOrMalformedFilesAreClearErrors) {
  const fs::path missing = fs::temp_directory_path() / "crowdsim_no_such_world_set.yaml";
  try {
    Make({{"file", missing.string()}});
    FAIL() << "expected an error";
  } catch (const PluginError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(missing.string()), std::string::npos) << what;
    EXPECT_NE(what.find("Fix"), std::string::npos) << what;
  }
  const fs::path bad = fs::temp_directory_path() /
                       ("crowdsim_bad_world_set_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream f(bad);
    f << "format: crowdsim-world-set/1\nworlds:\n  - name: x\n    bounds: [0, 0, 1]\n";
  }
  try {
    Make({{"file", bad.string()}});
    FAIL() << "expected an error";
  } catch (const PluginError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(bad.string()), std::string::npos) << what;
    EXPECT_NE(what.find("bounds"), std::string::npos) << what;
  }
  fs::remove(bad);
  try {
    Make({{"obstacles", std::int64_t{2}}});
    FAIL() << "expected an error";
  } catch (const PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("crowdsim-make-rect-worlds --obstacles 2"),
              std::string::npos)
        << e.what();
    // The tool is on PATH once installed; in a build tree it sits beside crowdsim-bench.
    EXPECT_NE(std::string(e.what()).find("build/bin/crowdsim-make-rect-worlds"), std::string::npos)
        << e.what();
  }
}

TEST_F(RandomRectPlugin, CustomFileIsUsedAndNamedInTheIdentity) {
  const fs::path file =
      crowdsim::testing::SourceDir() / "worlds" / "random_rect" / "obstacles_3_train.yaml";
  const auto world = Make({{"file", file.string()}, {"obstacles", std::int64_t{1}}});
  EXPECT_EQ(world->Identity(), "random_rect:file=obstacles_3_train.yaml");
  EXPECT_EQ(world->Make(Request(1, 2)).layout, "rect3_train_002");
}

}  // namespace
}  // namespace crowdsim
