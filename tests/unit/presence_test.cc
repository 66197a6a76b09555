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
