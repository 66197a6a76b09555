// The ORCA solver on small scenes: linear programs, obstacle processing, agents swapping,
// walls and corners, speed limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "crowdsim/rng.h"
#include "orca/geometry.h"
#include "orca/linear_program.h"
#include "orca/obstacles.h"
#include "orca/solver.h"
#include "orca_test_sim.h"

namespace crowdsim::orca {
namespace {

using testing::SimAgent;
using testing::TestSim;

// CrowdNav's human: radius 0.3 + 0.01 padding, v_pref 1, horizons 5 s, 0.25 s steps.
constexpr double kRadius = 0.31;
constexpr double kDt = 0.25;

SimAgent CrowdNavAgent(const Vec2& position, const Vec2& goal) {
  SimAgent a;
  a.state.position = position;
  a.state.radius = kRadius;
  a.params = OrcaParams{5.0, 5.0, 1.0};
  a.neighbor_dist = 10.0;
  a.goal = goal;
  return a;
}

double Penetration(const SimAgent& a, const Rect& r) {
  return a.state.radius - std::sqrt(RectDistanceSq(r, a.state.position));
}

TEST(OrcaLinearProgramTest, NoLinesClampsToTheSpeedDisc) {
  Vec2 result;
  EXPECT_EQ(SolveLinearProgram2({}, 1.0, Vec2(3.0, 4.0), false, &result), 0u);
  EXPECT_NEAR(result.x(), 0.6, 1e-12);
  EXPECT_NEAR(result.y(), 0.8, 1e-12);
  EXPECT_EQ(SolveLinearProgram2({}, 1.0, Vec2(0.3, 0.4), false, &result), 0u);
  EXPECT_EQ(result, Vec2(0.3, 0.4));
}

TEST(OrcaLinearProgramTest, ProjectsOnAViolatedLine) {
  // Feasible side is the left of a line along -x through (0, 0.5): y <= 0.5.
  const std::array<OrcaLine, 1> lines = {OrcaLine{Vec2(0.0, 0.5), Vec2(-1.0, 0.0)}};
  Vec2 result;
  EXPECT_EQ(SolveLinearProgram2(lines, 2.0, Vec2(0.2, 1.0), false, &result), 1u);
  EXPECT_NEAR(result.x(), 0.2, 1e-12);
  EXPECT_NEAR(result.y(), 0.5, 1e-12);
}

TEST(OrcaLinearProgramTest, InfeasibleSoftLinesMinimiseTheWorstViolation) {
  // y <= -0.5 and y >= 0.5 cannot both hold: LP3 settles in the middle.
  const std::array<OrcaLine, 2> lines = {OrcaLine{Vec2(0.0, -0.5), Vec2(-1.0, 0.0)},
                                         OrcaLine{Vec2(0.0, 0.5), Vec2(1.0, 0.0)}};
  Vec2 result;
  const std::size_t fail = SolveLinearProgram2(lines, 2.0, Vec2(1.0, 0.0), false, &result);
  ASSERT_EQ(fail, 1u);
  SolveLinearProgram3(lines, 0, fail, 2.0, &result);
  EXPECT_NEAR(result.y(), 0.0, 1e-9);
}

TEST(OrcaObstaclesTest, RectanglesBecomeCounterClockwiseConvexPolygons) {
  const std::array<Rect, 2> rects = {Rect::FromCorners(0, 0, 2, 1), Rect::FromCorners(5, 5, 5, 7)};
  const OrcaObstacles obstacles = OrcaObstacles::FromRects(rects);
  ASSERT_EQ(obstacles.num_polygons(), 2);
  const auto v = obstacles.vertices();
  ASSERT_EQ(v.size(), 6u);  // a box and a flat (segment) one
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(v[i].convex);
    EXPECT_EQ(v[v[i].next].prev, i);
    // Counter-clockwise: each next vertex turns left.
    EXPECT_GT(LeftOf(v[v[i].prev].point, v[i].point, v[v[i].next].point), 0.0);
  }
  EXPECT_EQ(v[0].direction, Vec2(1.0, 0.0));
  EXPECT_EQ(v[4].next, 5);
  EXPECT_EQ(v[5].next, 4);

  // Seen from below, only the bottom edge of the box faces the agent.
  std::vector<ObstacleNeighbor> near;
  obstacles.Query(Vec2(1.0, -1.0), 3.0, &near);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near[0].vertex, 0);
  EXPECT_DOUBLE_EQ(near[0].dist_sq, 1.0);
  // From a diagonal, two edges, nearest first.
  obstacles.Query(Vec2(3.0, -0.5), 5.0, &near);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_LE(near[0].dist_sq, near[1].dist_sq);
}

// Every query gives each edge facing the point within range, nearest first, equal distances in
// insertion order, among many boxes that touch, share sides or are flat walls, also from far
// outside.
TEST(OrcaObstaclesTest, QueryGivesEveryFacingEdgeInRangeNearestFirst) {
  Rng rng(41);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Rect> rects;
    const int count = 8 + static_cast<int>(rng.Below(120));
    for (int i = 0; i < count; ++i) {
      // On a 1 m lattice half of the time: shared sides and equal distances.
      const bool lattice = trial % 2 == 0;
      const double x = lattice ? static_cast<double>(rng.Below(30)) : rng.Uniform(0, 30);
      const double y = lattice ? static_cast<double>(rng.Below(30)) : rng.Uniform(0, 30);
      const double w = rng.Below(6) == 0 ? 0.0 : (lattice ? 1.0 : rng.Uniform(0.1, 3));
      const double h = lattice ? 1.0 : rng.Uniform(0.1, 3);
      rects.push_back(Rect::FromCorners(x, y, x + w, y + h));
    }
    const OrcaObstacles obstacles = OrcaObstacles::FromRects(rects);
    const auto v = obstacles.vertices();
    std::vector<ObstacleNeighbor> got;
    for (int q = 0; q < 50; ++q) {
      const Vec2 p = q % 10 == 0 ? Vec2(rng.Uniform(-40, 70), rng.Uniform(-40, 70))
                                 : Vec2(rng.Uniform(-2, 32), rng.Uniform(-2, 32));
      const double range = q % 7 == 0 ? 60.0 : rng.Uniform(0.5, 8);
      std::vector<ObstacleNeighbor> scan;
      for (int i = 0; i < static_cast<int>(v.size()); ++i) {
        if (LeftOf(v[i].point, v[v[i].next].point, p) >= 0.0) continue;
        const double d2 = SegmentDistanceSq(v[i].point, v[v[i].next].point, p);
        if (d2 < range * range) scan.push_back({d2, i});
      }
      std::stable_sort(scan.begin(), scan.end(),
                       [](const auto& a, const auto& b) { return a.dist_sq < b.dist_sq; });
      obstacles.Query(p, range, &got);
      SCOPED_TRACE("trial " + std::to_string(trial) + " query " + std::to_string(q));
      ASSERT_EQ(got.size(), scan.size());
      for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_EQ(got[k].vertex, scan[k].vertex);
        EXPECT_EQ(got[k].dist_sq, scan[k].dist_sq);
      }
    }
  }
}

TEST(OrcaSolverTest, FreeAgentTakesItsPreferredVelocity) {
  const OrcaAgent self{Vec2::Zero(), Vec2::Zero(), kRadius};
  const Vec2 v = ComputeOrcaVelocity(self, {}, OrcaObstacles(), OrcaParams{}, Vec2(0.6, 0.0), kDt);
  EXPECT_EQ(v, Vec2(0.6, 0.0));
}

// Two agents walking at each other; `offset` (m) shifts them sideways in opposite senses.
// Returns the smallest gap between their discs over the run.
double SwapHeadOn(double offset, TestSim* sim) {
  sim->AddAgent(CrowdNavAgent(Vec2(-4.0, -offset), Vec2(4.0, -offset)));
  sim->AddAgent(CrowdNavAgent(Vec2(4.0, offset), Vec2(-4.0, offset)));
  double min_gap = kInfinity;
  for (int step = 0; step < 80; ++step) {
    for (auto& a : sim->agents()) a.pref_velocity = testing::TowardsGoal(a);
    sim->Step();
    min_gap = std::min(min_gap, testing::MinPairGap(sim->agents()));
  }
  return min_gap;
}

TEST(OrcaSolverTest, TwoAgentsSwapHeadOnWithoutOverlap) {
  for (const double offset : {5e-4, 0.05, 0.2}) {
    TestSim sim(kDt, OrcaObstacles());
    EXPECT_GE(SwapHeadOn(offset, &sim), 0.0) << "the agents overlapped, offset " << offset;
    for (const auto& a : sim.agents()) {
      EXPECT_LT((a.state.position - a.goal).norm(), 0.2) << "did not arrive, offset " << offset;
    }
  }
}

TEST(OrcaSolverTest, ExactlySymmetricHeadOnStopsShortWithoutOverlap) {
  // Perfect symmetry is ORCA's known deadlock (RVO2's examples perturb the preferred
  // velocities for this reason): both agents only slow down. They must still never touch.
  TestSim sim(kDt, OrcaObstacles());
  EXPECT_GE(SwapHeadOn(0.0, &sim), 0.0);
  EXPECT_EQ(sim.agents()[0].state.position.y(), 0.0);
}

TEST(OrcaSolverTest, NeverFasterThanMaxSpeed) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Rect> rects;
  for (int k = 0; k < 6; ++k) {
    const Vec2 c(4.0 * u(rng), 4.0 * u(rng));
    rects.push_back(Rect{c, c + Vec2(0.5 + std::abs(u(rng)), 0.5 + std::abs(u(rng)))});
  }
  const OrcaObstacles obstacles = OrcaObstacles::FromRects(rects);
  std::vector<OrcaAgent> neighbours;
  double worst_ratio = 0.0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double max_speed = 0.5 + 1.5 * std::abs(u(rng));
    OrcaAgent self{Vec2(5.0 * u(rng), 5.0 * u(rng)), Vec2(2.0 * u(rng), 2.0 * u(rng)), kRadius};
    neighbours.clear();
    const int count = trial % 11;
    for (int k = 0; k < count; ++k) {
      // Some neighbours overlap the agent: the overlap branch must respect the limit too.
      neighbours.push_back({self.position + Vec2(1.5 * u(rng), 1.5 * u(rng)),
                            Vec2(2.0 * u(rng), 2.0 * u(rng)), kRadius});
    }
    const Vec2 pref(3.0 * u(rng), 3.0 * u(rng));
    const Vec2 v = ComputeOrcaVelocity(self, neighbours, obstacles, OrcaParams{5.0, 5.0, max_speed},
                                       pref, kDt);
    ASSERT_TRUE(v.allFinite()) << "trial " << trial;
    worst_ratio = std::max(worst_ratio, v.norm() / max_speed);
  }
  EXPECT_LE(worst_ratio, 1.0 + 1e-12);
}

// Every agent of every step keeps out of the wall; returns the worst penetration seen (m).
double RunAgainstWall(TestSim* sim, const Rect& wall, int steps, const Vec2& push) {
  double worst = -kInfinity;
  for (int step = 0; step < steps; ++step) {
    for (auto& a : sim->agents()) a.pref_velocity = push;
    sim->Step();
    for (const auto& a : sim->agents()) worst = std::max(worst, Penetration(a, wall));
  }
  return worst;
}

TEST(OrcaSolverTest, AgentSlidingAlongAWallNeverEntersIt) {
  const Rect wall = Rect::FromCorners(-5.0, -1.0, 5.0, 0.0);
  const std::array<Rect, 1> rects = {wall};
  for (const double angle_deg : {-90.0, -60.0, -30.0, -10.0}) {
    TestSim sim(kDt, OrcaObstacles::FromRects(rects));
    sim.AddAgent(CrowdNavAgent(Vec2(-2.0, 0.8), Vec2::Zero()));
    const double a = angle_deg * std::numbers::pi / 180.0;
    const double worst = RunAgainstWall(&sim, wall, 40, 2.0 * Vec2(std::cos(a), std::sin(a)));
    EXPECT_LE(worst, 1e-9) << "pushing at " << angle_deg << " deg";
  }
}

TEST(OrcaSolverTest, AgentsDrivenIntoACornerNeverEnterIt) {
  const Rect box = Rect::FromCorners(0.0, 0.0, 4.0, 4.0);
  const std::array<Rect, 1> rects = {box};
  // Agents all round the top-right corner, each heading for the box's centre at speed 2.
  TestSim sim(kDt, OrcaObstacles::FromRects(rects));
  for (int k = 0; k < 12; ++k) {
    const double a = (-90.0 + 22.5 * k) * std::numbers::pi / 180.0;
    SimAgent agent =
        CrowdNavAgent(Vec2(4.0, 4.0) + 2.0 * Vec2(std::cos(a), std::sin(a)), Vec2(2, 2));
    agent.params.max_speed = 2.0;
    if (Penetration(agent, box) > -0.05) continue;  // only start where it is clear
    sim.AddAgent(agent);
  }
  ASSERT_GE(sim.agents().size(), 6u);
  double worst = -kInfinity;
  for (int step = 0; step < 60; ++step) {
    for (auto& a : sim.agents()) a.pref_velocity = 2.0 * (a.goal - a.state.position).normalized();
    sim.Step();
    for (const auto& a : sim.agents()) worst = std::max(worst, Penetration(a, box));
  }
  EXPECT_LE(worst, 1e-9);
}

TEST(OrcaSolverTest, AgentPushedByACrowdNeverEntersTheWall) {
  const Rect wall = Rect::FromCorners(-10.0, -1.0, 10.0, 0.0);
  const std::array<Rect, 1> rects = {wall};
  TestSim sim(kDt, OrcaObstacles::FromRects(rects));
  // A 5 x 4 block of agents above the wall, all walking into it; the front row gets pushed.
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 5; ++col) {
      sim.AddAgent(CrowdNavAgent(Vec2(-1.4 + 0.7 * col, 0.35 + 0.7 * row), Vec2::Zero()));
    }
  }
  const double worst = RunAgainstWall(&sim, wall, 60, Vec2(0.0, -1.0));
  EXPECT_LE(worst, 1e-9);
}

}  // namespace
}  // namespace crowdsim::orca
