#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/collision_world.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

constexpr double kPi = std::numbers::pi;

std::shared_ptr<const StaticMap> MakeMap(std::vector<Rect> rects) {
  auto map = std::make_shared<StaticMap>();
  map->name = "lidar_test";
  map->bounds = Rect::FromCorners(-5, -5, 5, 5);
  map->rectangles = std::move(rects);
  return map;
}

// A 10 x 10 room (0.1 m walls), a box and a 1 mm thin wall.
std::shared_ptr<const StaticMap> Room() {
  return MakeMap({
      Rect::FromCorners(-5.0, -5.0, 5.0, -4.9),
      Rect::FromCorners(-5.0, 4.9, 5.0, 5.0),
      Rect::FromCorners(-5.0, -5.0, -4.9, 5.0),
      Rect::FromCorners(4.9, -5.0, 5.0, 5.0),
      Rect::FromCorners(1.0, 1.0, 2.0, 3.0),
      Rect::FromCorners(-2.0, -3.0, -1.999, 3.0),
  });
}

double Cast(const CollisionWorld& world, const Vec2& origin, double angle, double max_range,
            std::span<const Circle> discs = {}) {
  double range = -1.0;
  world.CastRays(origin, std::span<const double>(&angle, 1), max_range, discs, &range);
  return range;
}

TEST(CastRays, BeamHitsABoxFace) {
  CollisionWorld world(Room());
  EXPECT_NEAR(Cast(world, Vec2(0, 2), 0.0, 5.0), 1.0, 1e-12);
  EXPECT_NEAR(Cast(world, Vec2(1.5, 0), kPi / 2, 5.0), 1.0, 1e-12);
  EXPECT_NEAR(Cast(world, Vec2(3.5, 2.5), kPi, 5.0), 1.5, 1e-12);
  // Slanted: from (0, 1.5) at atan(0.5) the beam meets x = 1 at y = 2.
  EXPECT_NEAR(Cast(world, Vec2(0, 1.5), std::atan(0.5), 5.0), std::hypot(1.0, 0.5), 1e-12);
}

TEST(CastRays, BeamHitsACornerExactly) {
  CollisionWorld world(Room());
  // Through the corner (1, 1) into the box.
  EXPECT_NEAR(Cast(world, Vec2(0, 0), kPi / 4, 5.0), std::sqrt(2.0), 1e-12);
  // Along the box's top edge line: it touches from the corner (1, 3) on; grazing counts.
  EXPECT_NEAR(Cast(world, Vec2(0, 3), 0.0, 5.0), 1.0, 1e-12);
  // Just above that edge it flies on to the right wall at x = 4.9.
  EXPECT_NEAR(Cast(world, Vec2(0, 3.001), 0.0, 5.0), 4.9, 1e-12);
}

TEST(CastRays, BeamHitsAHuman) {
  CollisionWorld world(Room());
  const Circle human{Vec2(-1.0, 0.0), 0.3};
  EXPECT_NEAR(Cast(world, Vec2(0, 0), kPi, 5.0, std::span(&human, 1)), 0.7, 1e-12);
  EXPECT_NEAR(Cast(world, Vec2(0, 0), kPi, 5.0), 1.999, 1e-12);  // the thin wall behind
  // Off-centre: the beam along y = 0.18 meets the disc where x = -1 + 0.24.
  EXPECT_NEAR(Cast(world, Vec2(0, 0.18), kPi, 5.0, std::span(&human, 1)), 0.76, 1e-12);
  // Inside a human: 0.
  EXPECT_EQ(Cast(world, Vec2(-1.1, 0), 0.0, 5.0, std::span(&human, 1)), 0.0);
}

TEST(CastRays, BeamHittingNothingReportsMaxRange) {
  CollisionWorld world(Room());
  EXPECT_EQ(Cast(world, Vec2(0, 0), kPi / 2, 3.0), 3.0);
  EXPECT_EQ(Cast(world, Vec2(0, 0), -kPi / 2, 4.0), 4.0);
  EXPECT_NEAR(Cast(world, Vec2(0, 0), -kPi / 2, 5.0), 4.9, 1e-12);
  const Circle far{Vec2(0.0, 4.0), 0.3};  // 3.7 away, beyond a 3 m range
  EXPECT_EQ(Cast(world, Vec2(0, 0), kPi / 2, 3.0, std::span(&far, 1)), 3.0);
}

// A room with random boxes and an origin outside all of them.
struct RandomScene {
  std::shared_ptr<const StaticMap> map;
  Vec2 origin;
};

RandomScene MakeRandomScene(std::mt19937_64& rng, int boxes) {
  std::uniform_real_distribution<double> pos(-4.5, 4.5);
  std::uniform_real_distribution<double> size(0.01, 2.0);
  std::vector<Rect> rects = Room()->rectangles;
  rects.resize(4);  // the walls only
  for (int i = 0; i < boxes; ++i) {
    const double x = pos(rng), y = pos(rng);
    rects.push_back(Rect::FromCorners(x, y, x + size(rng), y + size(rng)));
  }
  Vec2 origin;
  bool free = false;
  while (!free) {
    origin = Vec2(pos(rng), pos(rng));
    free = true;
    for (const Rect& r : rects) free = free && PointToRectDistance(origin, r) > 1e-3;
  }
  return {MakeMap(std::move(rects)), origin};
}

// The fast scan (one broadphase query, exact slabs) equals Bullet's rayTest per beam.
TEST(CastRays, EqualsBulletRayTestOnRandomRooms) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> phase(-kPi, kPi);
  double worst = 0.0;
  int hits = 0;
  for (int scene = 0; scene < 200; ++scene) {
    const RandomScene s = MakeRandomScene(rng, 1 + scene % 8);
    CollisionWorld world(s.map);
    std::vector<double> angles(45);
    const double start = phase(rng);
    for (int k = 0; k < 45; ++k) angles[k] = start + k * kPi / 44;
    const double max_range = 2.0 + scene % 5;
    std::vector<double> fast(45), bullet(45);
    world.CastRays(s.origin, angles, max_range, {}, fast.data());
    world.CastRaysBullet(s.origin, angles, max_range, bullet.data());
    for (int k = 0; k < 45; ++k) {
      EXPECT_NEAR(fast[k], bullet[k], 1e-6) << "scene " << scene << " beam " << k;
      worst = std::max(worst, std::abs(fast[k] - bullet[k]));
      hits += fast[k] < max_range;
    }
  }
  EXPECT_GT(hits, 2000);  // most beams hit something: the comparison is not vacuous
  std::ostringstream worst_text;
  worst_text << worst;
  RecordProperty("worst_abs_difference", worst_text.str());
}

// The fast scan equals the exact 2D ray test against every shape, humans included.
TEST(CastRays, EqualsBruteForceExactScan) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> pos(-4.5, 4.5);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int scene = 0; scene < 200; ++scene) {
    const RandomScene s = MakeRandomScene(rng, scene % 10);
    CollisionWorld world(s.map);
    std::vector<Circle> discs;
    for (int h = 0; h < 6; ++h) discs.push_back({Vec2(pos(rng), pos(rng)), 0.3});
    std::vector<double> angles(30);
    for (double& a : angles) a = angle(rng);
    std::vector<double> fast(angles.size());
    world.CastRays(s.origin, angles, 4.0, discs, fast.data());
    for (size_t k = 0; k < angles.size(); ++k) {
      const Vec2 dir(std::cos(angles[k]), std::sin(angles[k]));
      double expected = 4.0;
      for (const Rect& r : s.map->rectangles) {
        expected = std::min(expected, RayRectDistance(s.origin, dir, r));
      }
      for (const Circle& c : discs) {
        expected = std::min(expected, RayCircleDistance(s.origin, dir, c.center, c.radius));
      }
      EXPECT_NEAR(fast[k], expected, 1e-9) << "scene " << scene << " beam " << k;
    }
  }
}

// ---- the lidar2d plugin ----

class Lidar2dPlugin : public ::testing::Test {
 protected:
  Lidar2dPlugin() : registry_({testing::PluginDir()}) {}

  std::shared_ptr<Sensor> Make(std::int64_t beams, double fov_deg, double max_range = 5.0,
                               bool see_humans = true) {
    const LoadedPlugin& p = registry_.Load("lidar2d", PluginKind::kSensor);
    Params params = Params::Defaults(p.schema);
    params.Set("beams", beams);
    params.Set("fov_deg", fov_deg);
    params.Set("max_range", max_range);
    params.Set("see_humans", see_humans);
    return registry_.MakeSensor(p, params);
  }

  SensorReading Sense(const Sensor& sensor, const CollisionWorld& world, const Vec2& pos,
                      double heading, std::span<const AgentState> humans = {}) {
    AgentState robot;
    robot.position = pos;
    robot.heading = heading;
    const Frame frame = Frame::Make(pos, heading);
    SensorReading reading;
    sensor.Sense(SenseInput{robot, frame, humans, world}, &reading);
    return reading;
  }

  PluginRegistry registry_;
};

TEST_F(Lidar2dPlugin, DefaultsAre45BeamsOver180Degrees) {
  const LoadedPlugin& p = registry_.Load("lidar2d", PluginKind::kSensor);
  auto sensor = registry_.MakeSensor(p, Params::Defaults(p.schema));
  CollisionWorld world(Room());
  const SensorReading r = Sense(*sensor, world, Vec2(0, 0), 0.0);
  ASSERT_EQ(r.angles.size(), 45u);
  ASSERT_EQ(r.ranges.size(), 45u);
  EXPECT_EQ(r.max_range, 5.0);
  EXPECT_NEAR(r.angles.front(), -kPi / 2, 1e-15);
  EXPECT_NEAR(r.angles.back(), kPi / 2, 1e-15);
  EXPECT_EQ(r.angles[22], 0.0);  // odd count: the centre beam is exactly the heading
  for (size_t k = 1; k < 45; ++k) EXPECT_NEAR(r.angles[k] - r.angles[k - 1], kPi / 44, 1e-15);
  for (size_t k = 0; k < 45; ++k) EXPECT_EQ(r.angles[k], -r.angles[44 - k]);
}

TEST_F(Lidar2dPlugin, FullCircleLeavesTheEndpointOut) {
  auto sensor = Make(8, 360.0);
  CollisionWorld world(Room());
  const SensorReading r = Sense(*sensor, world, Vec2(0, 0), 0.0);
  ASSERT_EQ(r.angles.size(), 8u);
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(r.angles[k], k * kPi / 4, 1e-15);
}

TEST_F(Lidar2dPlugin, OneBeamLooksAhead) {
  auto sensor = Make(1, 90.0);
  CollisionWorld world(Room());
  const SensorReading r = Sense(*sensor, world, Vec2(0, 2), 0.0);
  ASSERT_EQ(r.angles.size(), 1u);
  EXPECT_EQ(r.angles[0], 0.0);
  EXPECT_NEAR(r.ranges[0], 1.0, 1e-12);
}

TEST_F(Lidar2dPlugin, AnglesAreRelativeToTheHeading) {
  // Three beams at -45, 0, 45 deg from (1.5, 0) looking up (+y): world angles 45, 90, 135.
  auto sensor = Make(3, 90.0);
  CollisionWorld world(Room());
  const SensorReading r = Sense(*sensor, world, Vec2(1.5, 0), kPi / 2);
  ASSERT_EQ(r.ranges.size(), 3u);
  EXPECT_NEAR(r.angles[0], -kPi / 4, 1e-15);
  EXPECT_NEAR(r.ranges[1], 1.0, 1e-12);
  // World 45 deg passes under the box (y = 0.5 at x = 2) to the right wall x = 4.9 at y = 3.4.
  EXPECT_NEAR(r.ranges[0], 3.4 * std::sqrt(2.0), 1e-9);
  // World 135 deg passes under the box and over the thin wall (y = 3.499 > 3 at x = -1.999);
  // the top wall is 4.9 * sqrt(2) > 5 away: nothing within range.
  EXPECT_EQ(r.ranges[2], 5.0);
}

TEST_F(Lidar2dPlugin, SeesHumansUnlessTurnedOff) {
  CollisionWorld world(Room());
  AgentState human;
  human.position = Vec2(-1.0, 0.0);
  human.radius = 0.3;
  const std::vector<AgentState> humans{human};
  const SensorReading seen = Sense(*Make(1, 90.0), world, Vec2(0, 0), kPi, humans);
  EXPECT_NEAR(seen.ranges[0], 0.7, 1e-12);
  const SensorReading blind = Sense(*Make(1, 90.0, 5.0, false), world, Vec2(0, 0), kPi, humans);
  EXPECT_NEAR(blind.ranges[0], 1.999, 1e-12);
}

TEST_F(Lidar2dPlugin, RangesMatchTheCollisionWorldScan) {
  auto sensor = Make(45, 180.0, 4.0);
  CollisionWorld world(Room());
  AgentState human;
  human.position = Vec2(0.5, 1.0);
  const std::vector<AgentState> humans{human};
  const double heading = 0.7;
  const SensorReading r = Sense(*sensor, world, Vec2(-0.5, -0.5), heading, humans);
  // The sensor rotates its beams' fixed directions by the heading's cosine and sine.
  std::vector<Vec2> directions;
  for (double a : r.angles) {
    directions.emplace_back(std::cos(a) * std::cos(heading) - std::sin(a) * std::sin(heading),
                            std::sin(a) * std::cos(heading) + std::cos(a) * std::sin(heading));
  }
  const Circle disc{human.position, human.radius};
  std::vector<double> expected(45);
  world.CastRays(Vec2(-0.5, -0.5), directions, 4.0, std::span(&disc, 1), expected.data());
  EXPECT_EQ(r.ranges, expected);
  // The same beams given as world angles (a sine and cosine each): equal but for rounding.
  std::vector<double> world_angles;
  for (double a : r.angles) world_angles.push_back(a + heading);
  std::vector<double> by_angle(45);
  world.CastRays(Vec2(-0.5, -0.5), world_angles, 4.0, std::span(&disc, 1), by_angle.data());
  for (size_t k = 0; k < by_angle.size(); ++k) EXPECT_NEAR(r.ranges[k], by_angle[k], 1e-12) << k;
  EXPECT_EQ(r.max_range, 4.0);
}

// Noise and dropouts: the configured statistics over many steps, none by default, and the same
// draws for the same (episode, step).
TEST_F(Lidar2dPlugin, RangeNoiseAndDropoutsHaveTheirConfiguredStatistics) {
  const LoadedPlugin& p = registry_.Load("lidar2d", PluginKind::kSensor);
  Params params = Params::Defaults(p.schema);
  params.Set("beams", std::int64_t{3});
  params.Set("fov_deg", 2.0);  // three beams within a degree of the heading: the wall 1.9 m ahead
  const auto exact = registry_.MakeSensor(p, params);
  params.Set("range_noise", 0.1);
  params.Set("dropout_prob", 0.2);
  const auto noisy = registry_.MakeSensor(p, params);
  CollisionWorld world(Room());
  AgentState robot;
  robot.position = Vec2(0, 3);
  const Frame frame = Frame::Make(robot.position, kPi / 2);  // up: the top wall at y = 4.9
  const auto read = [&](const Sensor& sensor, std::uint64_t seed, int step) {
    SensorReading r;
    sensor.Sense(SenseInput{robot, frame, {}, world, seed, step}, &r);
    return r;
  };
  const double truth = read(*exact, 1, 0).ranges[1];
  EXPECT_NEAR(truth, 1.9, 1e-12);
  EXPECT_EQ(read(*exact, 7, 3).ranges, read(*exact, 8, 4).ranges);  // exact: no draws
  int dropped = 0;
  int returns = 0;
  double sum = 0.0, sum_sq = 0.0;
  constexpr int kSteps = 20000;
  for (int step = 0; step < kSteps; ++step) {
    const SensorReading r = read(*noisy, 42, step);
    EXPECT_EQ(r.ranges, read(*noisy, 42, step).ranges);  // same episode and step: same draws
    if (r.ranges[1] == 5.0) {
      ++dropped;
      continue;
    }
    ++returns;
    sum += r.ranges[1] - truth;
    sum_sq += (r.ranges[1] - truth) * (r.ranges[1] - truth);
  }
  // Binomial: 0.2 +- 4 standard errors (0.0028); the noise's standard deviation within 3%.
  EXPECT_NEAR(dropped / double(kSteps), 0.2, 4 * std::sqrt(0.2 * 0.8 / kSteps));
  const double mean = sum / returns;
  EXPECT_NEAR(mean, 0.0, 4 * 0.1 / std::sqrt(returns));
  EXPECT_NEAR(std::sqrt(sum_sq / returns - mean * mean), 0.1, 0.003);
  // Another episode draws other noise.
  EXPECT_NE(read(*noisy, 42, 5).ranges, read(*noisy, 43, 5).ranges);
}

TEST_F(Lidar2dPlugin, RejectsZeroFieldOfViewAndRange) {
  EXPECT_THROW(Make(45, 0.0), PluginError);
  EXPECT_THROW(Make(45, 180.0, 0.0), PluginError);
}

}  // namespace
}  // namespace crowdsim
