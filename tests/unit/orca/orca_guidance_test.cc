// The roadmap and the path following that keep ORCA agents from stalling behind walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "crowdsim/rng.h"
#include "orca/geometry.h"
#include "orca/guidance.h"
#include "orca/obstacles.h"
#include "orca/roadmap.h"
#include "orca/solver.h"
#include "orca/yielding.h"

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

// Shortest distance from start to goal over the roadmap's graph, built here segment by segment
// with the roadmap's own rules (Dijkstra; kInfinity when they are not connected).
double ReferenceDistance(const Roadmap& roadmap, const Vec2& start, const Vec2& goal) {
  const auto& rects = roadmap.rects();
  const auto& nodes = roadmap.nodes();
  const int n = static_cast<int>(nodes.size());
  const double slack = 1e-9;
  const double c_start = std::max(0.0, roadmap.CappedClearance(start) - slack);
  const double c_goal = std::max(0.0, roadmap.CappedClearance(goal) - slack);
  if (roadmap.Visible(start, goal)) return (goal - start).norm();
  std::vector<double> dist(n + 1, kInfinity);  // nodes, then the goal
  std::vector<char> done(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    if (SegmentClear(rects, start, nodes[i], c_start)) dist[i] = (nodes[i] - start).norm();
  }
  for (;;) {
    int i = -1;
    for (int k = 0; k <= n; ++k) {
      if (!done[k] && dist[k] < kInfinity && (i < 0 || dist[k] < dist[i])) i = k;
    }
    if (i < 0 || i == n) return dist[n];
    done[i] = 1;
    for (int j = 0; j < n; ++j) {
      if (j == i || done[j]) continue;
      if (SegmentClear(rects, nodes[i], nodes[j], roadmap.clearance() - slack)) {
        dist[j] = std::min(dist[j], dist[i] + (nodes[j] - nodes[i]).norm());
      }
    }
    if (SegmentClear(rects, nodes[i], goal, c_goal)) {
      dist[n] = std::min(dist[n], dist[i] + (goal - nodes[i]).norm());
    }
  }
}

// The search asks whether a node sees the goal only when it reaches that node: the paths it
// finds are still shortest, and it still finds none exactly when there is none.
TEST(OrcaRoadmapTest, ShortestPathIsShortestAmongManyBoxes) {
  Rng rng(17);
  int connected = 0, unconnected = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<Rect> rects;
    for (int i = 0; i < 25; ++i) {
      const double x = rng.Uniform(-9, 8), y = rng.Uniform(-9, 8);
      rects.push_back(Rect::FromCorners(x, y, x + rng.Uniform(0.2, 3), y + rng.Uniform(0.2, 3)));
    }
    const Rect bounds = Rect::FromCorners(-10, -10, 10, 10);
    const Roadmap roadmap(rects, bounds, kRadius, 0.2);
    for (int q = 0; q < 15; ++q) {
      const Vec2 start(rng.Uniform(-10, 10), rng.Uniform(-10, 10));
      const Vec2 goal(rng.Uniform(-10, 10), rng.Uniform(-10, 10));
      const double expected = ReferenceDistance(roadmap, start, goal);
      const std::vector<Vec2> path = roadmap.ShortestPath(start, goal);
      SCOPED_TRACE("trial " + std::to_string(trial) + " query " + std::to_string(q));
      if (expected == kInfinity) {
        EXPECT_TRUE(path.empty());
        ++unconnected;
        continue;
      }
      ASSERT_FALSE(path.empty());
      ++connected;
      EXPECT_EQ(path.back(), goal);
      double length = 0.0;
      Vec2 previous = start;
      for (const Vec2& p : path) {
        length += (p - previous).norm();
        previous = p;
      }
      EXPECT_NEAR(length, expected, 1e-9 * (1.0 + expected));
    }
  }
  EXPECT_GT(connected, 20);
  EXPECT_GT(unconnected, 0);  // starts or goals walled in (or inside a box)
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

// ---- Yielding (deadlock resolution) ----

TEST(OrcaYieldingTest, RankPutsWalkersBeforeSettledAgentsThenHigherIndices) {
  AgentState walker;
  walker.position = Vec2(0, 0);
  walker.goal = Vec2(5, 0);
  AgentState settled;
  settled.position = Vec2(1, 1);
  settled.goal = Vec2(1.2, 1);
  EXPECT_GT(YieldRank(walker, 0), YieldRank(settled, 3));
  EXPECT_GT(YieldRank(walker, 2), YieldRank(walker, 1));
  EXPECT_GT(YieldRank(settled, 2), YieldRank(settled, 1));
}

TEST(OrcaYieldingTest, OnlyTheLowerRankOfAJamBacksOffAlongItsTrail) {
  const YieldSettings settings;  // 8 decisions, 0.5 m, 2-8 s
  Yielding low(settings);
  Yielding high(settings);
  // Both walked east to x = 0 and stand there, nose to nose with a jammed neighbour.
  for (double x = -2.0; x < 0.0; x += 0.25) {
    EXPECT_FALSE(low.Observe(Vec2(x, 0)));
    EXPECT_FALSE(high.Observe(Vec2(x, 0)));
  }
  const YieldNeighbour above_low{Vec2(0.62, 0), Vec2::Zero(), kRadius, 1.0, /*rank=*/2};
  const YieldNeighbour below_high{Vec2(0.62, 0), Vec2::Zero(), kRadius, 1.0, /*rank=*/0};
  Vec2 target;
  int low_steps = 0;
  for (int step = 0; step < settings.jam_steps; ++step) {
    if (low.Observe(Vec2::Zero()) &&
        low.Step(Vec2::Zero(), kRadius, 1, kDt, {&above_low, 1}, &target)) {
      break;
    }
    ++low_steps;
    ASSERT_FALSE(high.Observe(Vec2::Zero()) &&
                 high.Step(Vec2::Zero(), kRadius, 1, kDt, {&below_high, 1}, &target))
        << "the higher rank gave way";
  }
  EXPECT_LT(low_steps, settings.jam_steps) << "stuck but never gave way";
  EXPECT_TRUE(low.yielding());
  EXPECT_LT(target.x(), 0.0) << "it should walk back the way it came";
  EXPECT_EQ(low.yields(), 1);
  EXPECT_EQ(high.yields(), 0);

  // The other stays jammed against it: the yield ends at yield_max_time, not before.
  int yield_steps = 1;
  while (low.Observe(Vec2::Zero()) &&
         low.Step(Vec2::Zero(), kRadius, 1, kDt, {&above_low, 1}, &target)) {
    ++yield_steps;
    ASSERT_LT(yield_steps, 1000);
  }
  EXPECT_TRUE(low.finished());
  EXPECT_NEAR(yield_steps * kDt, settings.max_time, kDt);
}

// Two agents meet head-on in an 8 m long, 1 m wide passage, too narrow for them to pass each
// other (their ways cross it from opposite corners, as in the random worlds); returns
// how many reach their goals within `seconds`, and the worst wall penetration (m).
int MeetInAPassage(bool yield, double seconds, double* worst_penetration) {
  StaticMap map;
  map.bounds = Rect::FromCorners(-10, -10, 10, 10);
  map.rectangles = {Rect::FromCorners(-4, 0.5, 4, 3), Rect::FromCorners(-4, -3, 4, -0.5)};
  const OrcaObstacles obstacles = OrcaObstacles::FromMap(map);
  std::array<AgentState, 2> agents;
  agents[0].position = Vec2(-6, -1);
  agents[0].goal = Vec2(6, -1);
  agents[1].position = Vec2(6, 1);
  agents[1].goal = Vec2(-6, 1);
  std::array<Guidance, 2> guidance;
  std::array<Yielding, 2> yielding;
  for (auto& g : guidance) g.Reset(SharedRoadmap(map, kRadius, 0.2));
  std::array<bool, 2> arrived = {false, false};
  *worst_penetration = -kInfinity;
  for (double t = 0.0; t < seconds; t += kDt) {
    std::array<Vec2, 2> velocities;
    for (int i = 0; i < 2; ++i) {
      const AgentState& self = agents[i];
      const AgentState& other = agents[1 - i];
      GuidanceTarget target = guidance[i].Next(self.position, self.goal);
      const YieldNeighbour n{other.position, other.velocity, kRadius, 1.0, YieldRank(other, 1 - i)};
      Vec2 back;
      if (yield && yielding[i].Observe(self.position) &&
          yielding[i].Step(self.position, kRadius, YieldRank(self, i), kDt, {&n, 1}, &back)) {
        target = {back, false};
      }
      const OrcaAgent me{self.position, self.velocity, kRadius};
      const OrcaAgent them{other.position, other.velocity, kRadius};
      velocities[i] = ComputeOrcaVelocity(me, {&them, 1}, obstacles, OrcaParams{5.0, 5.0, 1.0},
                                          PreferredVelocity(self.position, target, 1.0), kDt);
    }
    for (int i = 0; i < 2; ++i) {
      agents[i].velocity = velocities[i];
      agents[i].position += velocities[i] * kDt;
      arrived[i] = arrived[i] || (agents[i].position - agents[i].goal).norm() < kRadius;
      for (const Rect& r : map.rectangles) {
        *worst_penetration = std::max(*worst_penetration,
                                      kRadius - std::sqrt(RectDistanceSq(r, agents[i].position)));
      }
    }
  }
  return static_cast<int>(arrived[0]) + static_cast<int>(arrived[1]);
}

TEST(OrcaYieldingTest, HeadOnMeetingInAOneMetrePassageResolves) {
  double penetration = 0.0;
  // Why yielding exists: ORCA alone freezes both agents nose to nose in the passage.
  EXPECT_EQ(MeetInAPassage(false, 60.0, &penetration), 0);
  EXPECT_LE(penetration, 1e-9);
  // The lower rank backs out of the passage, the other follows it out and goes by: 12 m
  // each at 1 m/s, plus the way back out (8 m passage) and in again.
  EXPECT_EQ(MeetInAPassage(true, 45.0, &penetration), 2);
  EXPECT_LE(penetration, 1e-9);
}

// A pair 2 m apart: the centre is 1 m away, beyond the 0.5 m threshold, so the member heads along
// (goal direction + 2 x centre direction) at v_pref; within it, or alone, the velocity stays.
TEST(OrcaGroupTest, AFarMemberHeadsTowardsItsGroup) {
  const Vec2 partner[] = {Vec2(0.0, 2.0)};
  const Vec2 v = KeepWithGroup(Vec2::Zero(), Vec2(1.2, 0.0), 1.2, partner);
  EXPECT_NEAR(v.norm(), 1.2, 1e-12);
  EXPECT_NEAR(v.y() / v.x(), 2.0, 1e-12);
  const Vec2 near[] = {Vec2(0.0, 0.9)};
  EXPECT_EQ(KeepWithGroup(Vec2::Zero(), Vec2(1.2, 0.0), 1.2, near), Vec2(1.2, 0.0));
  EXPECT_EQ(KeepWithGroup(Vec2::Zero(), Vec2(1.2, 0.0), 1.2, {}), Vec2(1.2, 0.0));
}

}  // namespace
}  // namespace crowdsim::orca
