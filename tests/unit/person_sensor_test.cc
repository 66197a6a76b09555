#include <gtest/gtest.h>

#include <numbers>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/collision_world.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

constexpr double kPi = std::numbers::pi;

class PersonPlugin : public ::testing::Test {
 protected:
  PersonPlugin() : registry_({testing::PluginDir()}), world_(std::make_shared<StaticMap>()) {}

  std::shared_ptr<Sensor> Make(double max_range) {
    const LoadedPlugin& p = registry_.Load("person", PluginKind::kSensor);
    Params params = Params::Defaults(p.schema);
    params.Set("max_range", max_range);
    return registry_.MakeSensor(p, params);
  }

  SensorReading Sense(const Sensor& sensor, const Vec2& pos, double heading,
                      std::span<const AgentState> humans) {
    AgentState robot;
    robot.position = pos;
    robot.heading = heading;
    const Frame frame = Frame::Make(pos, heading);
    SensorReading reading;
    reading.people.resize(3);  // stale content must be replaced, not appended to
    sensor.Sense(SenseInput{robot, frame, humans, world_}, &reading);
    return reading;
  }

  static AgentState Human(Vec2 pos, Vec2 vel, double radius) {
    AgentState h;
    h.position = pos;
    h.velocity = vel;
    h.radius = radius;
    return h;
  }

  PluginRegistry registry_;
  CollisionWorld world_;
};

TEST_F(PersonPlugin, DefaultIsUnlimited) {
  const LoadedPlugin& p = registry_.Load("person", PluginKind::kSensor);
  auto sensor = registry_.MakeSensor(p, Params::Defaults(p.schema));
  const std::vector<AgentState> humans{Human(Vec2(100, 0), Vec2(0, 0), 0.3),
                                       Human(Vec2(1, 1), Vec2(0, 0), 0.3)};
  const SensorReading r = Sense(*sensor, Vec2(0, 0), 0.0, humans);
  ASSERT_EQ(r.people.size(), 2u);
  EXPECT_EQ(r.people[0].position, Vec2(100, 0));
  EXPECT_TRUE(r.ranges.empty());
}

TEST_F(PersonPlugin, PositionsAndVelocitiesAreInTheRobotFrame) {
  auto sensor = Make(0.0);
  // Robot at (1, 2) heading +y (90 deg): the robot's x axis is world +y, its y axis world -x.
  const std::vector<AgentState> humans{Human(Vec2(1, 5), Vec2(0, -1), 0.3),
                                       Human(Vec2(-1, 2), Vec2(0.5, 0), 0.25)};
  const SensorReading r = Sense(*sensor, Vec2(1, 2), kPi / 2, humans);
  ASSERT_EQ(r.people.size(), 2u);
  EXPECT_NEAR(r.people[0].position.x(), 3.0, 1e-12);  // straight ahead, 3 m
  EXPECT_NEAR(r.people[0].position.y(), 0.0, 1e-12);
  EXPECT_NEAR(r.people[0].velocity.x(), -1.0, 1e-12);  // coming towards the robot
  EXPECT_NEAR(r.people[0].velocity.y(), 0.0, 1e-12);
  EXPECT_EQ(r.people[0].radius, 0.3);
  // 2 m to the robot's left (facing +y, world -x is the robot's +y).
  EXPECT_NEAR(r.people[1].position.x(), 0.0, 1e-12);
  EXPECT_NEAR(r.people[1].position.y(), 2.0, 1e-12);
  EXPECT_NEAR(r.people[1].velocity.x(), 0.0, 1e-12);
  EXPECT_NEAR(r.people[1].velocity.y(), -0.5, 1e-12);
  EXPECT_EQ(r.people[1].radius, 0.25);
}

TEST_F(PersonPlugin, MaxRangeDropsFarHumansAndKeepsOrder) {
  auto sensor = Make(3.0);
  const std::vector<AgentState> humans{
      Human(Vec2(0, 2.9), Vec2(0, 0), 0.3),    // in
      Human(Vec2(4, 0), Vec2(0, 0), 0.3),      // out (4 m)
      Human(Vec2(-3, 0), Vec2(0, 0), 0.3),     // on the limit: in
      Human(Vec2(2.2, 2.2), Vec2(0, 0), 0.5),  // 3.11 m: out, although its disc reaches in
      Human(Vec2(1, -1), Vec2(1, 0), 0.3),     // in
  };
  const SensorReading r = Sense(*sensor, Vec2(0, 0), 0.0, humans);
  ASSERT_EQ(r.people.size(), 3u);
  EXPECT_EQ(r.people[0].position, Vec2(0, 2.9));
  EXPECT_EQ(r.people[1].position, Vec2(-3, 0));
  EXPECT_EQ(r.people[2].position, Vec2(1, -1));
  EXPECT_EQ(r.people[2].velocity, Vec2(1, 0));
}

// A limited sensor whose reuse of the reading grows it (more in range than it held) and shrinks
// it again: everybody in range, in the crowd's order, nothing left over.
TEST_F(PersonPlugin, ALimitedReadingGrowsAndShrinksWithTheCrowdInRange) {
  auto sensor = Make(3.0);
  std::vector<AgentState> humans;
  for (int i = 0; i < 6; ++i) humans.push_back(Human(Vec2(0.4 * i, 0.1), Vec2(i, 0), 0.3));
  AgentState robot;
  const Frame frame = Frame::Make(Vec2::Zero(), 0.0);
  SensorReading reading;
  reading.people.resize(2);  // fewer than will be in range
  sensor->Sense(SenseInput{robot, frame, humans, world_}, &reading);
  ASSERT_EQ(reading.people.size(), 6u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(reading.people[i].velocity, Vec2(i, 0)) << i;
  humans[1].position = Vec2(5, 0);  // out of range now
  sensor->Sense(SenseInput{robot, frame, humans, world_}, &reading);
  ASSERT_EQ(reading.people.size(), 5u);
  EXPECT_EQ(reading.people[1].velocity, Vec2(2, 0));
  EXPECT_EQ(reading.people[4].velocity, Vec2(5, 0));
}

TEST_F(PersonPlugin, NoHumansNoPeople) {
  auto sensor = Make(0.0);
  const SensorReading r = Sense(*sensor, Vec2(0, 0), 0.0, {});
  EXPECT_TRUE(r.people.empty());
}

}  // namespace
}  // namespace crowdsim
