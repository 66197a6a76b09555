// The roadmap and the path following that keep ORCA agents from stalling behind walls.
#include "orca_guidance.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "orca_geometry.h"
#include "orca_obstacles.h"
#include "orca_roadmap.h"
#include "orca_solver.h"

namespace crowdsim::orca {
namespace {

constexpr double kRadius = 0.31;
constexpr double kDt = 0.25;

// A 6 m wall across the straight line from (0, -5) to (0, 5).
StaticMap WallMap() {
  StaticMap map;
  map.name = "wall";
  map.bounds = Rect::FromCorners(-10, -10, 10, 10);
  map.rectangles = {Rect::FromCorners(-3.0, -0.5, 3.0, 0.5)};
  return map;
}

TEST(OrcaRoadmapTest, NodesKeepClearanceAndEdgesAreClear) {
  const StaticMap map = WallMap();
  const Roadmap roadmap(map.rectangles, map.bounds, kRadius, 0.2);
  ASSERT_EQ(roadmap.nodes().size(), 4u);
  EXPECT_EQ(roadmap.num_edges(), 4u);  // round the wall; the diagonals cross it
  for (const Vec2& n : roadmap.nodes()) {
    EXPECT_NEAR(DistanceToRects(map.rectangles, n), std::sqrt(2.0) * (kRadius + 0.2), 1e-12);
  }
}

TEST(OrcaRoadmapTest, ShortestPathGoesRoundTheWall) {
  const StaticMap map = WallMap();
  const Roadmap roadmap(map.rectangles, map.bounds, kRadius, 0.2);
  const std::vector<Vec2> path = roadmap.ShortestPath(Vec2(0, -5), Vec2(0, 5));
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path.back(), Vec2(0, 5));
  Vec2 previous(0, -5);
  for (const Vec2& p : path) {
    EXPECT_TRUE(SegmentClear(map.rectangles, previous, p, kRadius - 1e-9));
    previous = p;
  }
  // In sight: no detour.
  EXPECT_EQ(roadmap.ShortestPath(Vec2(5, -5), Vec2(5, 5)), std::vector<Vec2>{Vec2(5, 5)});
}

TEST(OrcaRoadmapTest, EnclosedGoalHasNoPath) {
  StaticMap map;
  map.rectangles = {Rect::FromCorners(-3, -3, 3, -2), Rect::FromCorners(-3, 2, 3, 3),
                    Rect::FromCorners(-3, -2, -2, 2), Rect::FromCorners(2, -2, 3, 2)};
  const Roadmap roadmap(map.rectangles, map.bounds, kRadius, 0.2);
  EXPECT_TRUE(roadmap.ShortestPath(Vec2(-6, 0), Vec2(0, 0)).empty());
}

TEST(OrcaRoadmapTest, SharedRoadmapIsBuiltOncePerMapAndRadius) {
  const StaticMap map = WallMap();
  StaticMap copy = map;  // another object with the same layout
  const auto a = SharedRoadmap(map, kRadius, 0.2);
  EXPECT_EQ(SharedRoadmap(copy, kRadius, 0.2), a);
  EXPECT_NE(SharedRoadmap(map, 0.46, 0.2), a);
  copy.rectangles[0].max.x() = 4.0;
  EXPECT_NE(SharedRoadmap(copy, kRadius, 0.2), a);
}

TEST(OrcaGuidanceTest, PreferredVelocityFollowsCrowdNavsRule) {
  EXPECT_TRUE(PreferredVelocity(Vec2(0, 0), {Vec2(3, 4), true}, 1.2).isApprox(Vec2(0.72, 0.96)));
  EXPECT_EQ(PreferredVelocity(Vec2(0, 0), {Vec2(0.3, 0.4), true}, 1.2), Vec2(0.3, 0.4));
  // An intermediate waypoint is passed at full speed.
  EXPECT_TRUE(PreferredVelocity(Vec2(0, 0), {Vec2(0.3, 0.4), false}, 1.0).isApprox(Vec2(0.6, 0.8)));
}

// Walks one ORCA agent from (0, -5) to (0, 5) behind the wall for at most `seconds`;
// returns its final distance to the goal, and the worst wall penetration (m).
double WalkBehindWall(bool guided, double seconds, double* worst_penetration, int* plans) {
  const StaticMap map = WallMap();
  const OrcaObstacles obstacles = OrcaObstacles::FromMap(map);
  Guidance guidance;
  guidance.Reset(guided ? SharedRoadmap(map, kRadius, 0.2) : nullptr);
  OrcaAgent self{Vec2(0.0, -5.0), Vec2::Zero(), kRadius};
  const Vec2 goal(0.0, 5.0);
  *worst_penetration = -kInfinity;
  for (double t = 0.0; t < seconds; t += kDt) {
    const Vec2 pref = PreferredVelocity(self.position, guidance.Next(self.position, goal), 1.0);
    self.velocity = ComputeOrcaVelocity(self, {}, obstacles, OrcaParams{5.0, 5.0, 1.0}, pref, kDt);
    self.position += self.velocity * kDt;
    *worst_penetration = std::max(
        *worst_penetration, kRadius - std::sqrt(RectDistanceSq(map.rectangles[0], self.position)));
  }
  *plans = guidance.plans();
  return (self.position - goal).norm();
}

TEST(OrcaGuidanceTest, AgentBehindAWallArrives) {
  double penetration = 0.0;
  int plans = 0;
  // 10 m straight; round the wall ~13 m at 1 m/s.
  EXPECT_LT(WalkBehindWall(true, 25.0, &penetration, &plans), 0.2);
  EXPECT_LE(penetration, 1e-9);
  EXPECT_EQ(plans, 1);
}

TEST(OrcaGuidanceTest, WithoutGuidanceTheSameAgentStalls) {
  // Why guidance exists: ORCA alone stops in front of a wall square to its goal.
  double penetration = 0.0;
  int plans = 0;
  EXPECT_GT(WalkBehindWall(false, 60.0, &penetration, &plans), 5.0);
  EXPECT_LE(penetration, 1e-9);
}

}  // namespace
}  // namespace crowdsim::orca
