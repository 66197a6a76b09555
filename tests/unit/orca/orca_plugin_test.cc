// The built `orca` plugin, loaded as the harness loads it, deciding on hand-made observations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <thread>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/bench/plugin_registry.h"
#include "orca/geometry.h"
#include "orca/guidance.h"
#include "orca/solver.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

class OrcaPluginTest : public ::testing::Test {
 protected:
  void SetUp() override {
    plugin_ = &registry_.Load("orca", PluginKind::kPolicy);
    params_ = Params::Defaults(plugin_->schema);
  }
  std::shared_ptr<Policy> Make() { return registry_.MakePolicy(*plugin_, params_); }
  /// A new policy reset as a human of an empty map (kept by the fixture).
  std::shared_ptr<Policy> MakeHuman() {
    auto policy = Make();
    EpisodeContext ctx;
    ctx.map = &empty_map_;
    ctx.role = AgentRole::kHuman;
    policy->Reset(ctx);
    return policy;
  }

  PluginRegistry registry_{{crowdsim::testing::PluginDir()}};
  StaticMap empty_map_;
  const LoadedPlugin* plugin_ = nullptr;
  Params params_;
};

AgentState Human(const Vec2& position, const Vec2& goal, const Vec2& velocity = Vec2::Zero()) {
  AgentState s;
  s.position = position;
  s.goal = goal;
  s.velocity = velocity;
  return s;
}

TEST_F(OrcaPluginTest, DeclaresCrowdNavDefaultsAndNeedsTheMap) {
  EXPECT_STREQ(plugin_->descriptor->name, "orca");
  EXPECT_DOUBLE_EQ(params_.GetDouble("neighbor_dist"), 10.0);
  EXPECT_EQ(params_.GetInt("max_neighbors"), 10);
  EXPECT_DOUBLE_EQ(params_.GetDouble("time_horizon"), 5.0);
  EXPECT_DOUBLE_EQ(params_.GetDouble("time_horizon_obst"), 5.0);
  EXPECT_DOUBLE_EQ(params_.GetDouble("radius_padding"), 0.01);
  EXPECT_DOUBLE_EQ(params_.GetDouble("safety_space"), 0.0);
  EXPECT_DOUBLE_EQ(params_.GetDouble("max_speed_factor"), 1.0);
  EXPECT_TRUE(params_.GetBool("guidance"));
  EXPECT_TRUE(params_.GetBool("others_pref_zero"));
  EXPECT_TRUE(params_.GetBool("yield"));
  EXPECT_EQ(params_.GetInt("yield_steps"), 8);
  EXPECT_DOUBLE_EQ(params_.GetDouble("yield_time"), 2.0);
  EXPECT_DOUBLE_EQ(params_.GetDouble("yield_max_time"), 8.0);
  EXPECT_TRUE(Make()->Needs().map);
}

TEST_F(OrcaPluginTest, HumanAvoidsAnotherHumanComingAtIt) {
  auto policy = MakeHuman();

  std::vector<AgentState> agents = {Human(Vec2(0, 0), Vec2(6, 0.05)),
                                    Human(Vec2(2, 0), Vec2(-6, 0), Vec2(-1, 0))};
  AgentIndex index;
  index.Rebuild(agents);
  Observation obs;
  obs.self = agents[0];
  obs.agents = &index;
  obs.self_index = 0;
  const Vec2 v = policy->Decide(obs).velocity;
  EXPECT_TRUE(v.allFinite());
  EXPECT_LE(v.norm(), 1.0 + 1e-12);
  EXPECT_GT(std::abs(v.y()), 0.05) << "it walked straight into the other human";

  // Alone, it walks straight to its goal at v_pref.
  std::vector<AgentState> alone = {agents[0]};
  index.Rebuild(alone);
  const Vec2 free = policy->Decide(obs).velocity;
  EXPECT_NEAR(free.norm(), 1.0, 1e-12);
  EXPECT_NEAR(free.y(), 0.05 / 6.0, 1e-3);
}

// One policy deciding on several threads at once (episodes on a pool's threads): each thread
// has its own scratch, made by its first decision, so each gets this thread's answers.
TEST_F(OrcaPluginTest, DecidesTheSameOnSeveralThreads) {
  auto policy = MakeHuman();

  // Two scenes with different numbers of neighbours: a shared scratch would mix them.
  const std::vector<AgentState> pair = {Human(Vec2(0, 0), Vec2(6, 0.05)),
                                        Human(Vec2(2, 0), Vec2(-6, 0), Vec2(-1, 0))};
  const std::vector<AgentState> crowd = {
      Human(Vec2(0, 0), Vec2(0, 6)), Human(Vec2(0.2, 1.5), Vec2(0, -6), Vec2(0, -1)),
      Human(Vec2(-1, 1), Vec2(3, 1), Vec2(0.8, 0)), Human(Vec2(1, 2), Vec2(-3, 2))};
  AgentIndex pair_index, crowd_index;
  pair_index.Rebuild(pair);
  crowd_index.Rebuild(crowd);
  auto observe = [](const std::vector<AgentState>& agents, const AgentIndex& index) {
    Observation obs;
    obs.self = agents[0];
    obs.agents = &index;
    obs.self_index = 0;
    return obs;
  };
  const Observation pair_obs = observe(pair, pair_index);
  const Observation crowd_obs = observe(crowd, crowd_index);
  const Vec2 pair_v = policy->Decide(pair_obs).velocity;
  const Vec2 crowd_v = policy->Decide(crowd_obs).velocity;
  ASSERT_NE(pair_v, crowd_v);

  auto decide_often = [&](const Observation& obs, const Vec2& expected, int* wrong) {
    for (int k = 0; k < 200; ++k) *wrong += policy->Decide(obs).velocity != expected;
  };
  int pair_wrong = 0, crowd_wrong = 0;
  std::thread pair_thread(decide_often, std::cref(pair_obs), std::cref(pair_v), &pair_wrong);
  std::thread crowd_thread(decide_often, std::cref(crowd_obs), std::cref(crowd_v), &crowd_wrong);
  pair_thread.join();
  crowd_thread.join();
  EXPECT_EQ(pair_wrong, 0);
  EXPECT_EQ(crowd_wrong, 0);
}

TEST_F(OrcaPluginTest, RobotSeesPeopleThroughItsPersonSensor) {
  auto robot = Make();
  auto human = Make();
  StaticMap map;
  EpisodeContext ctx;
  ctx.map = &map;
  robot->Reset(ctx);
  ctx.role = AgentRole::kHuman;
  human->Reset(ctx);

  // The robot walks up the y axis; its sensor frame has x towards the goal.
  const AgentState self = Human(Vec2(1, -3), Vec2(1, 4), Vec2(0, 0.5));
  const AgentState person = Human(Vec2(1.1, -1), Vec2(1, -6), Vec2(0.1, -0.8));
  const Frame frame = Frame::Make(self.position, std::numbers::pi / 2);

  Observation robot_obs;
  robot_obs.self = self;
  robot_obs.frame = frame;
  EXPECT_TRUE(robot->Decide(robot_obs).velocity.isApprox(Vec2(0, 1))) << "no sensor: straight";

  SensorReading reading;
  reading.sensor = "person";
  reading.people.push_back(
      {frame.PointToLocal(person.position), frame.VectorToLocal(person.velocity), 0.3});
  robot_obs.readings.push_back(reading);
  const Vec2 robot_v = robot->Decide(robot_obs).velocity;

  // The same scene as ground truth for a human policy: the same answer.
  std::vector<AgentState> agents = {self, person};
  AgentIndex index;
  index.Rebuild(agents);
  Observation human_obs;
  human_obs.self = self;
  human_obs.agents = &index;
  human_obs.self_index = 0;
  const Vec2 human_v = human->Decide(human_obs).velocity;
  EXPECT_NEAR((robot_v - human_v).norm(), 0.0, 1e-9);
  EXPECT_GT((robot_v - Vec2(0, 1)).norm(), 0.05) << "the robot ignored the person";
}

// The robot avoids its max_neighbors nearest people, nearest first, people at the same
// distance in the sensor's order; a decision with fewer people after one with more keeps
// nothing of the earlier one. Checked bit for bit against the solver on the expected list.
TEST_F(OrcaPluginTest, RobotTakesItsNearestPeopleTiesInSensorOrder) {
  params_.Set("max_neighbors", std::int64_t{2});
  auto robot = Make();
  StaticMap map;
  EpisodeContext ctx;
  ctx.map = &map;
  robot->Reset(ctx);

  const AgentState self = Human(Vec2(0, -3), Vec2(0, 4), Vec2(0, 0.5));
  // Heading 0: the sensor frame's round trip is exact, so the tie below stays a tie.
  const Frame frame = Frame::Make(self.position, 0.0);
  struct Person {
    Vec2 position, velocity;
  };
  // Two people 2 m away (A ahead, coming at the robot; B behind it, standing), one farther,
  // and last a nearer one beside the robot. A must be avoided, B would not matter.
  const std::vector<Person> people = {{Vec2(0, -1), Vec2(0, -1)},
                                      {Vec2(0, -5), Vec2(0, 0)},
                                      {Vec2(3, 1), Vec2(0, 0)},
                                      {Vec2(-1.5, -3), Vec2(0, 0)}};
  auto observe = [&](const std::vector<Person>& seen) {
    Observation obs;
    obs.self = self;
    obs.frame = frame;
    SensorReading reading;
    reading.sensor = "person";
    for (const Person& p : seen) {
      reading.people.push_back(
          {frame.PointToLocal(p.position), frame.VectorToLocal(p.velocity), 0.3});
    }
    obs.readings.push_back(reading);
    return obs;
  };
  // What the plugin must solve: the people as it reads them back, its padding, its settings.
  const double padding = 0.01;
  auto solve = [&](const Observation& obs, std::vector<int> chosen) {
    std::vector<orca::OrcaAgent> neighbours;
    for (int k : chosen) {
      const PersonObservation& p = obs.readings[0].people[static_cast<std::size_t>(k)];
      neighbours.push_back({obs.frame.origin + obs.frame.VectorToWorld(p.position),
                            obs.frame.VectorToWorld(p.velocity), p.radius + padding});
    }
    orca::OrcaParams params;
    params.max_speed = self.v_pref;
    const orca::OrcaAgent me{self.position, self.velocity, self.radius + padding};
    const Vec2 pref = orca::PreferredVelocity(self.position, {self.goal, true}, self.v_pref);
    return orca::ComputeOrcaVelocity(me, neighbours, orca::OrcaObstacles(), params, pref, 0.25);
  };

  const Observation all = observe(people);
  const Vec2 got = robot->Decide(all).velocity;
  EXPECT_EQ(got, solve(all, {3, 0})) << "the nearest, then the first of the tied pair";
  ASSERT_NE(solve(all, {3, 0}), solve(all, {3, 1})) << "the tie would not show";

  // Then two people only, on the same thread: the earlier decision's neighbours are gone.
  const Observation two = observe({people[2], people[0]});
  EXPECT_EQ(robot->Decide(two).velocity, solve(two, {1, 0}));
}

TEST_F(OrcaPluginTest, RejectsOthersPrefNonZero) {
  params_.Set("others_pref_zero", false);
  EXPECT_THROW(Make(), PluginError);
}

TEST_F(OrcaPluginTest, RejectsAYieldCappedBelowItsMinimum) {
  params_.Set("yield_time", 3.0);
  params_.Set("yield_max_time", 2.0);
  EXPECT_THROW(Make(), PluginError);
}

// A small crowd through the plugin, two-pass as the harness does it: six humans on both
// sides of a 6 m wall swap sides. Every one arrives and none touches the wall.
TEST_F(OrcaPluginTest, CrowdSwapsSidesRoundAWall) {
  StaticMap map;
  map.name = "wall";
  map.bounds = Rect::FromCorners(-10, -10, 10, 10);
  map.rectangles = {Rect::FromCorners(-3.0, -0.5, 3.0, 0.5)};
  std::vector<AgentState> agents;
  for (int k = 0; k < 3; ++k) {
    const double x = -1.0 + 1.0 * k;
    agents.push_back(Human(Vec2(x, -5), Vec2(-x, 5)));
    agents.push_back(Human(Vec2(x, 5), Vec2(-x, -5)));
  }
  std::vector<std::shared_ptr<Policy>> policies;
  EpisodeContext ctx;
  ctx.map = &map;
  ctx.role = AgentRole::kHuman;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    policies.push_back(Make());
    ctx.agent_id = static_cast<int>(i) + 1;
    policies.back()->Reset(ctx);
  }
  AgentIndex index;
  std::vector<Vec2> next(agents.size());
  double worst_wall = -kInfinity;
  double min_gap = kInfinity;
  for (int step = 0; step < 160; ++step) {  // 40 s
    index.Rebuild(agents);
    for (std::size_t i = 0; i < agents.size(); ++i) {
      Observation obs;
      obs.time = step * 0.25;
      obs.self = agents[i];
      obs.agents = &index;
      obs.self_index = static_cast<int>(i);
      next[i] = policies[i]->Decide(obs).velocity;
    }
    for (std::size_t i = 0; i < agents.size(); ++i) {
      agents[i].velocity = next[i];
      agents[i].position += next[i] * 0.25;
      worst_wall = std::max(
          worst_wall, agents[i].radius -
                          std::sqrt(orca::RectDistanceSq(map.rectangles[0], agents[i].position)));
      for (std::size_t j = 0; j < i; ++j) {
        min_gap = std::min(min_gap, (agents[i].position - agents[j].position).norm() - 0.6);
      }
    }
  }
  for (const auto& a : agents) EXPECT_LT((a.position - a.goal).norm(), 0.2);
  EXPECT_LE(worst_wall, 0.0);
  EXPECT_GE(min_gap, 0.0);
}

}  // namespace
}  // namespace crowdsim
