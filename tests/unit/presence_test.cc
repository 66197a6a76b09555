// People who appear and leave (HumanSpec::appear, leave): the absent are handed to no sensor,
// never hit, and marked in the trajectory; a crowd always present plays as before.
#include <gtest/gtest.h>

#include <vector>

#include "crowdsim/bench/episode.h"
#include "scripted.h"

namespace crowdsim {
namespace {

using testing::ConstantVelocityPolicy;
using testing::GoStraightPolicy;
using testing::MakeMap;
using testing::MakeScenario;

// Records, per reading, the scenario indices of the people it was handed.
class IdSensor final : public Sensor {
 public:
  void Sense(const SenseInput& in, SensorReading*) const override {
    std::vector<int>& ids = seen.emplace_back();
    for (std::size_t i = 0; i < in.humans.size(); ++i) ids.push_back(HumanId(in, i));
  }
  mutable std::vector<std::vector<int>> seen;
};

// The robot walks (0,-4) -> (0,4) through person 0 standing at the origin; person 1 stands aside.
Scenario Crossing(double appear0, double leave0) {
  Scenario s = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4),
                            {{Vec2(0, 0), Vec2(0, 0)}, {Vec2(3, 0), Vec2(3, 0)}});
  s.humans[0].appear = appear0;
  s.humans[0].leave = leave0;
  s.humans[1].appear = 1.0;
  s.humans[1].leave = 2.0;
  return s;
}

TEST(Presence, AnAbsentPersonIsNeitherSensedNorHit) {
  GoStraightPolicy robot;
  ConstantVelocityPolicy still(Vec2::Zero());
  IdSensor sensor;
  EpisodeAgents agents{&robot, {&still, &still}, {MountedSensor{"ids", &sensor}}, {}};
  const Scenario s = Crossing(/*appear0=*/100.0, kInfinity);
  Episode episode(s, SimConfig{}, agents, /*record_trajectory=*/true);
  const EpisodeResult& r = episode.Run();
  EXPECT_EQ(r.status, EpisodeStatus::kSuccess);  // through person 0's spot
  EXPECT_EQ(r.collided_human, -1);
  // Person 1 is sensed from 1 s to 2 s (steps 4..8) only, under its own index.
  ASSERT_EQ(sensor.seen.size(), 32u);
  for (std::size_t k = 0; k < sensor.seen.size(); ++k) {
    const bool present = k >= 4 && k <= 8;
    EXPECT_EQ(sensor.seen[k], present ? std::vector<int>{1} : std::vector<int>{}) << k;
    EXPECT_EQ(r.trajectory[k].Present(1), present) << k;
    EXPECT_FALSE(r.trajectory[k].Present(0)) << k;
  }
}

TEST(Presence, APersonPresentWhenTheRobotPassesIsHit) {
  GoStraightPolicy robot;
  ConstantVelocityPolicy still(Vec2::Zero());
  EpisodeAgents agents{&robot, {&still, &still}, {}, {}};
  // Present from 2 s on: the robot reaches it at about 3.4 s.
  const Scenario s = Crossing(/*appear0=*/2.0, kInfinity);
  Episode episode(s, SimConfig{}, agents);
  EXPECT_EQ(episode.Run().status, EpisodeStatus::kCollisionHuman);
  EXPECT_EQ(episode.result().collided_human, 0);
}

// Records how many agents each decision saw and whether self_index named the person itself.
class NeighbourCheck final : public Policy {
 public:
  Action Decide(const Observation& obs) override {
    seen.push_back(obs.agents->agents().size());
    self_ok = self_ok && obs.agents->agents()[static_cast<std::size_t>(obs.self_index)].position ==
                             obs.self.position;
    return Action{};
  }
  std::vector<std::size_t> seen;
  bool self_ok = true;
};

TEST(Presence, OtherPeopleSeeOnlyThePresentAndFindThemselves) {
  GoStraightPolicy robot;
  NeighbourCheck zero, one;
  EpisodeAgents agents{&robot, {&zero, &one}, {}, {}};
  Scenario s = Crossing(/*appear0=*/0.0, kInfinity);
  s.robot_start = Vec2(-4, -4);  // clear of both people
  s.robot_goal = Vec2(-4, 4);
  Episode episode(s, SimConfig{}, agents);
  for (int k = 0; k < 12; ++k) episode.Step();  // 3 s
  // Person 0 decides every step, seeing person 1 only from 1 s to 2 s (steps 4..8).
  ASSERT_EQ(zero.seen.size(), 12u);
  for (std::size_t k = 0; k < zero.seen.size(); ++k) {
    EXPECT_EQ(zero.seen[k], k >= 4 && k <= 8 ? 2u : 1u) << k;
  }
  EXPECT_EQ(one.seen.size(), 5u);  // person 1 decides only while present
  EXPECT_TRUE(zero.self_ok);
  EXPECT_TRUE(one.self_ok);
}

TEST(Presence, ACrowdAlwaysPresentIsHandedWhole) {
  GoStraightPolicy robot;
  ConstantVelocityPolicy still(Vec2::Zero());
  EpisodeAgents agents{&robot, {&still, &still}, {}, {}};
  const Scenario s = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4),
                                  {{Vec2(2, 0), Vec2(2, 0)}, {Vec2(3, 0), Vec2(3, 0)}});
  Episode episode(s, SimConfig{}, agents, /*record_trajectory=*/true);
  EXPECT_EQ(episode.present_humans().data(), episode.humans().data());  // no copy
  EXPECT_TRUE(episode.present_ids().empty());
  episode.Run();
  EXPECT_TRUE(episode.result().trajectory.back().present.empty());
}

}  // namespace
}  // namespace crowdsim
