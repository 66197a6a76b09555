// The crowdnav world plugin: CrowdNav's circle_crossing and square_crossing, exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/rng.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

class CrowdNavPlugin : public ::testing::Test {
 protected:
  std::shared_ptr<WorldSource> Make(std::map<std::string, ParamValue> values = {}) {
    const LoadedPlugin& p = registry_.Load("crowdnav", PluginKind::kWorld);
    Params params = Params::Defaults(p.schema);
    for (auto& [k, v] : values) params.Set(k, v);
    return registry_.MakeWorld(p, params);
  }
  PluginRegistry registry_{{crowdsim::testing::PluginDir()}};
};

ScenarioRequest Request(std::uint64_t seed, int humans = 5,
                        HumanGoalMode mode = HumanGoalMode::kStay) {
  ScenarioRequest r;
  r.seed = seed;
  r.num_humans = humans;
  r.goal_mode = mode;
  return r;
}

TEST_F(CrowdNavPlugin, CircleCrossingFollowsCrowdNav) {
  const auto world = Make();
  EXPECT_EQ(world->Identity(), "crowdnav:scenario=circle_crossing");
  EXPECT_EQ(world->LayoutCount(), 0);
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const Scenario s = world->Make(Request(seed));
    EXPECT_TRUE(s.map->rectangles.empty());
    EXPECT_EQ(s.robot_start, Vec2(0, -4));
    EXPECT_EQ(s.robot_goal, Vec2(0, 4));
    ASSERT_EQ(s.humans.size(), 5u);
    for (size_t i = 0; i < s.humans.size(); ++i) {
      const HumanSpec& h = s.humans[i];
      // On the 4 m circle, moved by noise of at most 0.5 m in x and in y.
      EXPECT_LE(std::abs(h.start.norm() - 4.0), 0.5 * std::numbers::sqrt2 + 1e-12);
      const double nearest = std::hypot(std::max(0.0, std::abs(h.start.x()) - 0.5),
                                        std::max(0.0, std::abs(h.start.y()) - 0.5));
      const double farthest = std::hypot(std::abs(h.start.x()) + 0.5, std::abs(h.start.y()) + 0.5);
      EXPECT_LE(nearest, 4.0 + 1e-12);
      EXPECT_GE(farthest, 4.0 - 1e-12);
      ASSERT_EQ(h.goals.size(), 1u);
      EXPECT_EQ(h.goals[0], -h.start);
      for (const Vec2& robot_point : {s.robot_start, s.robot_goal}) {
        EXPECT_GE((h.start - robot_point).norm(), 0.8);
        EXPECT_GE((h.goals[0] - robot_point).norm(), 0.8);
      }
      for (size_t j = 0; j < i; ++j) {
        EXPECT_GE((h.start - s.humans[j].start).norm(), 0.8);
        EXPECT_GE((h.start - s.humans[j].goals[0]).norm(), 0.8);
      }
    }
  }
}

TEST_F(CrowdNavPlugin, FirstHumanUsesCrowdNavsDrawOrder) {
  // Reference: generate_circle_crossing_human for the first human (only the robot placed).
  const auto world = Make();
  for (std::uint64_t seed : {1u, 2u, 3u, 77u}) {
    Rng rng(seed);
    Vec2 p;
    for (;;) {
      const double angle = rng.Uniform() * 2.0 * std::numbers::pi;
      const double nx = (rng.Uniform() - 0.5) * 1.0;
      const double ny = (rng.Uniform() - 0.5) * 1.0;
      p = Vec2(4.0 * std::cos(angle) + nx, 4.0 * std::sin(angle) + ny);
      bool collide = false;
      for (const Vec2& a : {Vec2(0, -4), Vec2(0, 4)}) {
        collide = collide || (p - a).norm() < 0.8;
      }
      if (!collide) break;
    }
    EXPECT_EQ(world->Make(Request(seed, 1)).humans.at(0).start, p) << seed;
  }
}

TEST_F(CrowdNavPlugin, SameSeedSameScenario) {
  const auto world = Make();
  const Scenario a = world->Make(Request(10)), b = world->Make(Request(10));
  const Scenario c = world->Make(Request(11));
  for (size_t i = 0; i < a.humans.size(); ++i) {
    EXPECT_EQ(a.humans[i].start, b.humans[i].start);
    EXPECT_EQ(a.humans[i].goals, b.humans[i].goals);
  }
  EXPECT_NE(a.humans[0].start, c.humans[0].start);
  EXPECT_EQ(a.map, c.map);
}

TEST_F(CrowdNavPlugin, SquareCrossingFollowsCrowdNav) {
  const auto world = Make({{"scenario", std::string("square_crossing")}});
  EXPECT_EQ(world->Identity(), "crowdnav:scenario=square_crossing");
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const Scenario s = world->Make(Request(seed));
    EXPECT_EQ(s.robot_start, Vec2(0, -4));
    for (size_t i = 0; i < s.humans.size(); ++i) {
      const HumanSpec& h = s.humans[i];
      const Vec2& g = h.goals.at(0);
      EXPECT_LE(std::abs(h.start.x()), 5.0);
      EXPECT_LE(std::abs(h.start.y()), 5.0);
      EXPECT_LE(std::abs(g.x()), 5.0);
      EXPECT_LE(std::abs(g.y()), 5.0);
      EXPECT_LE(h.start.x() * g.x(), 0.0) << "start and goal on opposite sides";
      EXPECT_GE((h.start - s.robot_start).norm(), 0.8);
      EXPECT_GE((g - s.robot_goal).norm(), 0.8);
      for (size_t j = 0; j < i; ++j) {
        EXPECT_GE((h.start - s.humans[j].start).norm(), 0.8);
        EXPECT_GE((g - s.humans[j].goals[0]).norm(), 0.8);
      }
    }
  }
}

TEST_F(CrowdNavPlugin, NewGoalsCrossBackAndForth) {
  const auto world = Make();
  const Scenario stay = world->Make(Request(3));
  const Scenario move = world->Make(Request(3, 5, HumanGoalMode::kNewGoal));
  for (size_t i = 0; i < move.humans.size(); ++i) {
    const HumanSpec& h = move.humans[i];
    EXPECT_EQ(h.start, stay.humans[i].start);
    ASSERT_EQ(h.goals.size(), 16u);
    for (size_t k = 0; k < h.goals.size(); ++k) {
      EXPECT_EQ(h.goals[k], k % 2 == 0 ? -h.start : h.start);
    }
  }
}

TEST_F(CrowdNavPlugin, RadiusAndCountAreParameters) {
  const auto world = Make({{"circle_radius", 6.0}});
  EXPECT_EQ(world->Identity(), "crowdnav:scenario=circle_crossing:circle_radius=6");
  const Scenario s = world->Make(Request(4, 10));
  EXPECT_EQ(s.robot_start, Vec2(0, -6));
  ASSERT_EQ(s.humans.size(), 10u);
  for (const HumanSpec& h : s.humans) EXPECT_LE(std::abs(h.start.norm() - 6.0), 0.71);
  EXPECT_THROW(Make()->Make(Request(1, 200)), std::runtime_error);
}

// A crowd too dense to place is an error that says how dense, and a size that holds it does.
TEST_F(CrowdNavPlugin, ACrowdThatDoesNotFitNamesItsDensityAndASizeThatFits) {
  auto message = [&](std::map<std::string, ParamValue> values, int humans, int seeds = 1) {
    try {
      for (int seed = 0; seed < seeds; ++seed) Make(values)->Make(Request(seed, humans));
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("(placed)");
  };
  const std::string circle = message({}, 30);
  EXPECT_NE(circle.find("circle_radius 4 m: 1.19 humans per metre of circle"), std::string::npos)
      << circle;
  const auto fix = circle.find("circle_radius >= ~");
  ASSERT_NE(fix, std::string::npos) << circle;
  const double radius = std::stod(circle.substr(fix + 18));
  EXPECT_EQ(message({{"circle_radius", radius}}, 30, 20), "(placed)");

  const std::string square = message({{"scenario", std::string("square_crossing")}}, 300);
  EXPECT_NE(square.find("square_width 10 m: 3 humans per m^2"), std::string::npos) << square;
  const auto sfix = square.find("square_width >= ~");
  ASSERT_NE(sfix, std::string::npos) << square;
  const double width = std::stod(square.substr(sfix + 17));
  EXPECT_EQ(
      message({{"scenario", std::string("square_crossing")}, {"square_width", width}}, 300, 20),
      "(placed)");
}

}  // namespace
}  // namespace crowdsim
