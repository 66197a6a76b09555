// The route sensor through its plugin: path distance and waypoint in open space, around a
// wall, without a free route, and a field cache that never mixes two worlds up.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/collision_world.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

// A 10 x 10 room; `wall_top` > -5 adds a wall at x = 0 from the floor up to wall_top.
std::shared_ptr<const StaticMap> Room(double wall_top) {
  auto map = std::make_shared<StaticMap>();
  map->name = "route_test";
  map->bounds = Rect::FromCorners(-5, -5, 5, 5);
  map->rectangles = {
      Rect::FromCorners(-5.0, -5.0, 5.0, -4.9), Rect::FromCorners(-5.0, 4.9, 5.0, 5.0),
      Rect::FromCorners(-5.0, -5.0, -4.9, 5.0), Rect::FromCorners(4.9, -5.0, 5.0, 5.0)};
  if (wall_top > -5.0) map->rectangles.push_back(Rect::FromCorners(-0.05, -5.0, 0.05, wall_top));
  return map;
}

class RoutePlugin : public ::testing::Test {
 protected:
  RoutePlugin() : registry_({testing::PluginDir()}) {
    const LoadedPlugin& p = registry_.Load("route", PluginKind::kSensor);
    sensor_ = registry_.MakeSensor(p, Params::Defaults(p.schema));
  }

  // {distance, waypoint x, waypoint y} for a robot at `from` heading for `goal`.
  std::vector<double> Sense(const CollisionWorld& world, const Vec2& from, const Vec2& goal) {
    AgentState robot;
    robot.position = from;
    robot.goal = goal;
    robot.radius = 0.3;
    robot.heading = HeadingToGoal(robot);
    const Frame frame = Frame::Make(from, robot.heading);
    SensorReading reading;
    sensor_->Sense(SenseInput{robot, frame, {}, world}, &reading);
    return reading.values;
  }

  PluginRegistry registry_;
  std::shared_ptr<Sensor> sensor_;
};

TEST_F(RoutePlugin, OpenSpaceIsTheStraightLine) {
  const CollisionWorld world(Room(-5.0));
  // Off every grid axis, so an 8-connected path alone would be longer and bent.
  const std::vector<double> v = Sense(world, Vec2(-3.0, -1.0), Vec2(3.5, 1.7));
  ASSERT_EQ(v.size(), 3u);
  EXPECT_NEAR(v[0], (Vec2(3.5, 1.7) - Vec2(-3.0, -1.0)).norm(), 1e-9);
  // One metre (the default lookahead) straight ahead in the frame that faces the goal.
  EXPECT_NEAR(v[1], 1.0, 1e-9);
  EXPECT_NEAR(v[2], 0.0, 1e-9);
  // Nearer than the lookahead: the goal itself.
  const std::vector<double> near = Sense(world, Vec2(1.0, 1.0), Vec2(1.3, 1.4));
  EXPECT_NEAR(near[0], 0.5, 1e-9);
  EXPECT_NEAR(near[1], 0.5, 1e-9);
  EXPECT_NEAR(near[2], 0.0, 1e-9);
}

TEST_F(RoutePlugin, LeadsAroundAWall) {
  // The wall leaves a gap from y = 3 to the ceiling (4.9): the route climbs to it and back.
  const CollisionWorld world(Room(3.0));
  const std::vector<double> v = Sense(world, Vec2(-2.0, 0.0), Vec2(2.0, 0.0));
  ASSERT_EQ(v.size(), 3u);
  // The shortest path keeps 0.35 m (radius 0.3 + margin 0.05) from the wall: tangents from
  // robot and goal to the discs of that radius round the wall's two top corners, the arcs over
  // them and the wall's 0.1 m between: 2 x (3.5609 + 0.3830) + 0.1 = 7.988 m. The grid's 16
  // directions may add up to 2.7%.
  const double shortest = 7.988;
  EXPECT_GT(v[0], shortest - 0.05);
  EXPECT_LT(v[0], 1.027 * shortest + 0.05);
  // The waypoint is one metre away, towards the gap: up and to the right of the robot.
  EXPECT_NEAR(std::hypot(v[1], v[2]), 1.0, 1e-9);
  EXPECT_GT(v[2], 0.8);
  EXPECT_GT(v[1], 0.0);
}

TEST_F(RoutePlugin, WithoutAFreeRouteFallsBackToTheStraightLine) {
  const CollisionWorld world(Room(5.0));  // the wall closes the room in two
  const std::vector<double> v = Sense(world, Vec2(-2.0, 0.0), Vec2(2.0, 0.0));
  ASSERT_EQ(v.size(), 3u);
  EXPECT_NEAR(v[0], 4.0, 1e-9);
  EXPECT_NEAR(v[1], 1.0, 1e-9);
  EXPECT_NEAR(v[2], 0.0, 1e-9);
}

// A 10 x 10 room split by a wall at x = 0 with a door `width` wide centred on y = 0.05 (a row
// of grid cell centres, so that the grid's 0.1 m cells can resolve a few centimetres of slack).
std::shared_ptr<const StaticMap> RoomWithDoor(double width) {
  auto map = std::const_pointer_cast<StaticMap>(Room(-5.0));
  map->rectangles.push_back(Rect::FromCorners(-0.05, -5.0, 0.05, 0.05 - width / 2));
  map->rectangles.push_back(Rect::FromCorners(-0.05, 0.05 + width / 2, 0.05, 5.0));
  return map;
}

TEST_F(RoutePlugin, ADoorNarrowerThanTheMarginStillLeadsThrough) {
  // 0.68 m: wider than the robot (0.6), narrower than radius + margin on both sides (0.7).
  const CollisionWorld world(RoomWithDoor(0.68));
  const std::vector<double> v = Sense(world, Vec2(-2.0, 2.0), Vec2(2.0, 2.0));
  ASSERT_EQ(v.size(), 3u);
  // Through the door, not the straight line through the wall (4 m): at least the two legs to
  // the door's centre, at most those legs and the grid's 2.7% (plus a cell).
  const double legs = std::hypot(2.0, 1.95) + std::hypot(2.0, 1.95);
  EXPECT_GT(v[0], legs - 0.05);
  EXPECT_LT(v[0], 1.027 * legs + 0.1);
  EXPECT_LT(v[2], -0.3);  // the waypoint turns towards the door, below the line to the goal
  // A door narrower than the robot: no route, the straight line.
  const CollisionWorld shut(RoomWithDoor(0.56));
  EXPECT_NEAR(Sense(shut, Vec2(-2.0, 2.0), Vec2(2.0, 2.0))[0], 4.0, 1e-9);
}

TEST_F(RoutePlugin, ADiagonalPassageIsOpen) {
  // Two blocks corner to corner with a diagonal gap of 0.7 m: the robot (0.6 m) fits through
  // with 5 cm to spare on each side, but no grid cell beside the cells along the gap is free,
  // so a rule that a diagonal move needs the cells it crosses free closes it (checked: with
  // that rule, no route at either clearance and the straight line comes back).
  auto map = std::const_pointer_cast<StaticMap>(Room(-5.0));
  const double g = 0.7 / std::sqrt(2.0);
  map->rectangles.push_back(Rect::FromCorners(-5.0, -5.0, 0.0, 0.0));
  map->rectangles.push_back(Rect::FromCorners(g, g, 5.0, 5.0));
  const CollisionWorld world(map);
  // The straight line (4.95 m) crosses the upper block; the route bends through the gap.
  const Vec2 from(3.0, -0.5), to(-0.5, 3.0), gap_centre(g / 2, g / 2);
  const double legs = (gap_centre - from).norm() + (to - gap_centre).norm();  // 5.705 m
  const std::vector<double> v = Sense(world, from, to);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_GT(v[0], legs - 0.05);
  EXPECT_LT(v[0], 1.027 * legs + 0.1);
}

TEST_F(RoutePlugin, ARobotBesideAWallDoesNotSeeThroughIt) {
  // A block 1.3 m thick; the robot 0.32 m below it, inside the clearance band (radius 0.3 +
  // margin 0.05), the goal straight across it. The band lets a reading start in blocked cells,
  // but only its width: the route goes around the block's end, not through it.
  auto map = std::const_pointer_cast<StaticMap>(Room(-5.0));
  map->rectangles.push_back(Rect::FromCorners(-3.0, 1.2, 1.4, 2.5));
  const CollisionWorld world(map);
  const Vec2 from(0.4, 0.88), to(-0.6, 3.5);
  const std::vector<double> v = Sense(world, from, to);
  ASSERT_EQ(v.size(), 3u);
  // Around the right end (x = 1.4 + 0.35): at least the legs to that corner's clearance.
  const Vec2 corner(1.75, 2.5);
  EXPECT_GT(v[0], (corner - from).norm() + (to - corner).norm() - 0.4);
  // The waypoint leads right along the block (in the frame facing the goal, up and left:
  // to the right and a little back), not towards the goal.
  EXPECT_LT(v[2], -0.5);
  EXPECT_LT(v[1], 0.0);
}

TEST_F(RoutePlugin, CachedFieldsBelongToTheirWorld) {
  // Same goal, same bounds, same number of rectangles: only the world tells them apart.
  const CollisionWorld open(Room(-4.0));  // a stub of wall, below the robot
  const CollisionWorld walled(Room(3.0));
  for (int round = 0; round < 2; ++round) {
    EXPECT_NEAR(Sense(open, Vec2(-2.0, 0.0), Vec2(2.0, 0.0))[0], 4.0, 1e-9) << round;
    EXPECT_GT(Sense(walled, Vec2(-2.0, 0.0), Vec2(2.0, 0.0))[0], 7.5) << round;
  }
  // A world built where a freed one was gets a field of its own.
  for (double top : {3.0, -4.0, 3.0}) {
    const CollisionWorld world(Room(top));
    const double d = Sense(world, Vec2(-2.0, 0.0), Vec2(2.0, 0.0))[0];
    if (top > 0.0) {
      EXPECT_GT(d, 7.5);
    } else {
      EXPECT_NEAR(d, 4.0, 1e-9);
    }
  }
}

TEST_F(RoutePlugin, ThirtyTwoEpisodesInTurnKeepTheirOwnFields) {
  // Thirty-two worlds read in turn, more than the cache keeps: each reading is its world's in
  // every round, fields evicted and rebuilt.
  std::vector<std::unique_ptr<CollisionWorld>> worlds;
  for (int k = 0; k < 32; ++k) {
    worlds.push_back(std::make_unique<CollisionWorld>(Room(k % 2 ? 3.0 : -4.0)));
  }
  for (int round = 0; round < 3; ++round) {
    for (int k = 0; k < 32; ++k) {
      if (k % 2) {
        EXPECT_GT(Sense(*worlds[k], Vec2(-2.0, 0.0), Vec2(2.0, 0.0))[0], 7.5) << k;
      } else {
        // Each open room's own start: a field of another world would give another distance.
        const double y = 0.1 * k;
        EXPECT_NEAR(Sense(*worlds[k], Vec2(-2.0, y), Vec2(2.0, 0.0))[0], std::hypot(4.0, y), 1e-9)
            << k;
      }
    }
  }
}

}  // namespace
}  // namespace crowdsim
