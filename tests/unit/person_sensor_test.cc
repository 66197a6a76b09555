#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/collision_world.h"
#include "suite_runs.h"
#include "temp_dir.h"
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

// Field of view and occlusion (issue 48): off by default, and then out of the config hash.
class PersonRealism : public ::testing::Test {
 protected:
  PersonRealism() : registry_({testing::PluginDir()}) {
    auto map = std::make_shared<StaticMap>();
    map->bounds = Rect::FromCorners(-10, -10, 10, 10);
    map->rectangles = {Rect::FromCorners(2.0, -0.5, 2.5, 0.5)};  // a pillar 2 m ahead
    world_ = std::make_unique<CollisionWorld>(map);
  }
  std::shared_ptr<Sensor> Make(double fov_deg, const std::string& occlusion) {
    const LoadedPlugin& p = registry_.Load("person", PluginKind::kSensor);
    Params params = Params::Defaults(p.schema);
    params.Set("fov_deg", fov_deg);
    params.Set("occlusion", occlusion);
    return registry_.MakeSensor(p, params);
  }
  /// The x of each person reported, the robot at the origin heading +x.
  std::vector<double> Seen(const Sensor& sensor, const std::vector<AgentState>& humans) {
    AgentState robot;
    const Frame frame = Frame::Make(Vec2::Zero(), 0.0);
    SensorReading reading;
    sensor.Sense(SenseInput{robot, frame, humans, *world_}, &reading);
    std::vector<double> xs;
    for (const PersonObservation& p : reading.people) xs.push_back(p.position.x());
    return xs;
  }
  static AgentState At(double x, double y) {
    AgentState h;
    h.position = Vec2(x, y);
    h.radius = 0.3;
    return h;
  }
  PluginRegistry registry_;
  std::unique_ptr<CollisionWorld> world_;
};

TEST_F(PersonRealism, ThePillarHidesWhoStandsBehindItOnlyWithOcclusion) {
  const std::vector<AgentState> humans{At(4.0, 0.0), At(4.0, 2.0), At(1.0, 0.0)};
  EXPECT_EQ(Seen(*Make(360, "none"), humans), (std::vector<double>{4.0, 4.0, 1.0}));
  // (4, 0) is behind the pillar, all three sight lines blocked; (4, 2) is clear.
  EXPECT_EQ(Seen(*Make(360, "obstacles"), humans), (std::vector<double>{4.0, 1.0}));
  // Half hidden: the pillar covers its centre line but not its upper edge.
  const std::vector<AgentState> edge{At(4.0, 0.8)};
  EXPECT_EQ(Seen(*Make(360, "obstacles"), edge), (std::vector<double>{4.0}));
}

TEST_F(PersonRealism, PeopleHidePeopleOnlyWhenAskedTo) {
  // Behind the person at (-2, 0) along the robot's back, away from the pillar.
  const std::vector<AgentState> humans{At(-2.0, 0.0), At(-4.0, 0.0)};
  EXPECT_EQ(Seen(*Make(360, "obstacles"), humans), (std::vector<double>{-2.0, -4.0}));
  EXPECT_EQ(Seen(*Make(360, "obstacles+people"), humans), (std::vector<double>{-2.0}));
  // A wider person behind is seen past the nearer one's edge.
  std::vector<AgentState> wide = humans;
  wide[1].radius = 0.9;
  EXPECT_EQ(Seen(*Make(360, "obstacles+people"), wide), (std::vector<double>{-2.0, -4.0}));
}

TEST_F(PersonRealism, OnlyPeopleInTheFieldOfViewAreReported) {
  // Bearings 0, 60, 100 and 180 degrees, all 3 m away and clear of the pillar's line.
  std::vector<AgentState> humans;
  for (const double deg : {0.0, 60.0, 100.0, 180.0}) {
    const double a = deg * kPi / 180.0;
    humans.push_back(At(3.0 * std::cos(a), 3.0 * std::sin(a) + (deg == 0.0 ? 3.0 : 0.0)));
  }
  humans[0] = At(1.0, 0.0);  // straight ahead, before the pillar
  EXPECT_EQ(Seen(*Make(360, "none"), humans).size(), 4u);
  EXPECT_EQ(Seen(*Make(180, "none"), humans).size(), 2u);  // 0 and 60 degrees
  EXPECT_EQ(Seen(*Make(90, "none"), humans).size(), 1u);   // straight ahead only
  EXPECT_EQ(Seen(*Make(220, "none"), humans).size(), 3u);  // 100 degrees too
}

// Over 20,000 readings (200 steps x 100 episodes' seeds) of one person in the open, 5 m ahead:
// the reported fraction is the detection probability and the position errors have the configured
// standard deviation, within 4 standard errors; the same (seed, step) gives the same reading.
TEST_F(PersonRealism, NoiseAndMissesFollowTheirParametersAndTheSeeds) {
  const LoadedPlugin& p = registry_.Load("person", PluginKind::kSensor);
  Params params = Params::Defaults(p.schema);
  params.Set("detection_prob", 0.9);
  params.Set("position_noise", 0.1);
  const auto sensor = registry_.MakeSensor(p, params);
  const std::vector<AgentState> humans{At(-5.0, 0.0)};
  AgentState robot;
  const Frame frame = Frame::Make(Vec2::Zero(), 0.0);
  const auto read = [&](std::uint64_t seed, int step) {
    SensorReading reading;
    sensor->Sense(SenseInput{robot, frame, humans, *world_, seed, step}, &reading);
    return reading.people;
  };
  int reported = 0, total = 0;
  double sum_x = 0, sum_xx = 0, sum_y = 0, sum_yy = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    for (int step = 0; step < 200; ++step) {
      const auto people = read(seed, step);
      ++total;
      if (people.empty()) continue;
      ++reported;
      const double dx = people[0].position.x() + 5.0, dy = people[0].position.y();
      sum_x += dx;
      sum_xx += dx * dx;
      sum_y += dy;
      sum_yy += dy * dy;
    }
  }
  const double rate = static_cast<double>(reported) / total;
  EXPECT_NEAR(rate, 0.9, 4.0 * std::sqrt(0.9 * 0.1 / total)) << rate;
  const double sd_x = std::sqrt(sum_xx / reported - std::pow(sum_x / reported, 2));
  const double sd_y = std::sqrt(sum_yy / reported - std::pow(sum_y / reported, 2));
  // The standard error of a standard deviation estimate: sigma / sqrt(2n).
  const double tolerance = 4.0 * 0.1 / std::sqrt(2.0 * reported);
  EXPECT_NEAR(sd_x, 0.1, tolerance) << sd_x;
  EXPECT_NEAR(sd_y, 0.1, tolerance) << sd_y;
  EXPECT_NEAR(sum_x / reported, 0.0, 4.0 * 0.1 / std::sqrt(reported));
  // Deterministic in (seed, step), different across steps.
  const auto a = read(7, 3), b = read(7, 3), c = read(7, 4);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());  // seed 7 draws a detection at steps 3 and 4
  ASSERT_FALSE(c.empty());
  EXPECT_EQ(a[0].position, b[0].position);
  EXPECT_NE(a[0].position, c[0].position);
  // Velocities stay true: a tracker's estimate is not modelled yet.
  EXPECT_EQ(a[0].velocity, Vec2::Zero());
}

// A realistic detector in a suite: the same episodes on one thread and on two (its noise comes
// from each episode's seed and step, not from a thread's state).
TEST_F(PersonRealism, ARealisticDetectorGivesTheSameEpisodesOnAnyThreads) {
  testing::TempDir dir;
  const auto file =
      dir.Write("real.yaml",
                "name: real\nepisodes: 6\nseed: 4\nworld: {source: random_rect, obstacles: 3}\n"
                "humans: {count: 5, policy: orca}\n"
                "robot: {sensors: [{type: person, fov_deg: 180, occlusion: obstacles+people, "
                "detection_prob: 0.9, position_noise: 0.1}]}\n"
                "rows:\n  - {label: orca, policy: orca}\n  - {label: sarl, policy: sarl}\n");
  const auto runs = testing::RunOnOneAndTwoThreads(file, dir.path());
  EXPECT_EQ(runs[0].episodes, runs[1].episodes);
}

TEST_F(PersonRealism, BadValuesAreRefusedAndDefaultsStayOutOfTheHash) {
  testing::TempDir dir;
  const auto suite = [&](const std::string& person) {
    return dir.Write("s.yaml",
                     "name: s\nepisodes: 1\nworld: {source: random_rect}\n"
                     "robot: {sensors: [" +
                         person +
                         "]}\n"
                         "rows:\n  - {label: a, policy: orca}\n");
  };
  PluginRegistry registry;
  const auto errors = [&](const std::string& person) {
    std::string all;
    for (const SuiteError& e : LoadSuite(suite(person), registry).errors) all += e.Format() + "\n";
    return all;
  };
  EXPECT_NE(errors("{type: person, fov_deg: 0}").find("fov_deg"), std::string::npos);
  EXPECT_NE(errors("{type: person, fov_deg: 400}").find("fov_deg"), std::string::npos);
  const std::string misspelt = errors("{type: person, occlusion: obstacle}");
  EXPECT_NE(misspelt.find("obstacles+people"), std::string::npos) << misspelt;
  // The defaults written out give the configuration of a suite that leaves them out.
  const auto hash = [&](const std::string& person) {
    return LoadSuite(suite(person), registry).suite->ConfigHash();
  };
  EXPECT_EQ(hash("person"), hash("{type: person, fov_deg: 360, occlusion: none}"));
  EXPECT_NE(hash("person"), hash("{type: person, fov_deg: 180}"));
  EXPECT_EQ(hash("person"), hash("{type: person, detection_prob: 1, position_noise: 0}"));
  EXPECT_NE(errors("{type: person, detection_prob: 1.5}").find("detection_prob"),
            std::string::npos);
  EXPECT_NE(errors("{type: person, position_noise: -0.1}").find("position_noise"),
            std::string::npos);
  const LoadedPlugin& p = registry_.Load("person", PluginKind::kSensor);
  for (const ParamSpec& spec : p.schema) {
    if (spec.name == "fov_deg") {
      EXPECT_EQ(std::get<double>(spec.default_value), 360.0);
      EXPECT_GT(spec.min, 0.0);
      EXPECT_EQ(spec.max, 360.0);
      EXPECT_FALSE(spec.hashed_at_default);
    }
    if (spec.name == "occlusion") {
      EXPECT_EQ(spec.choices, (std::vector<std::string>{"none", "obstacles", "obstacles+people"}));
      EXPECT_FALSE(spec.hashed_at_default);
    }
  }
}

TEST_F(PersonPlugin, NoHumansNoPeople) {
  auto sensor = Make(0.0);
  const SensorReading r = Sense(*sensor, Vec2(0, 0), 0.0, {});
  EXPECT_TRUE(r.people.empty());
}

}  // namespace
}  // namespace crowdsim
