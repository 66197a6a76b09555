// GlobalPlanner: clear paths for every planner, the margin kept (or relaxed only when the
// start or goal forces it), failure when there is no way, and the same path for the same
// seed in any thread.
#include "global_planner.h"

#include <gtest/gtest.h>

#include <thread>

#include "scripted.h"

namespace crowdsim::ompl_planner {
namespace {

// A 10 x 10 m room with a wall across the middle leaving a 1.2 m gap at its right end, and a
// block below: the straight line from bottom-left to top-left is blocked.
std::shared_ptr<const CollisionWorld> Room() {
  return std::make_shared<CollisionWorld>(crowdsim::testing::MakeRoom(
      {Rect::FromCorners(-5.0, -0.2, 3.8, 0.2), Rect::FromCorners(-1.0, -3.5, 1.0, -1.5)}));
}

PlanSettings Settings(const std::string& planner, std::int64_t samples = 1500) {
  PlanSettings s;
  s.planner = planner;
  s.plan_samples = samples;
  return s;
}

const Vec2 kStart(-4.0, -4.0);
const Vec2 kGoal(-4.0, 4.0);
constexpr double kRadius = 0.3;

void ExpectClearPath(const CollisionWorld& world, const PlanResult& r, const Vec2& start,
                     const Vec2& goal, double radius) {
  ASSERT_TRUE(r.solved);
  ASSERT_GE(r.path.size(), 2u);
  EXPECT_EQ(r.path.front(), start);
  EXPECT_EQ(r.path.back(), goal);
  for (std::size_t i = 1; i < r.path.size(); ++i) {
    EXPECT_TRUE(SegmentClear(world, r.path[i - 1], r.path[i], radius)) << "segment " << i;
  }
  EXPECT_NEAR(r.length, PathLength(r.path), 1e-12);
}

TEST(GlobalPlanner, EveryPlannerFindsAPathThatKeepsTheMargin) {
  const auto world = Room();
  for (const PlannerInfo& info : Planners()) {
    SCOPED_TRACE(info.name);
    const GlobalPlanner planner(world, Settings(info.name));
    const PlanResult r = planner.Plan(kStart, kGoal, kRadius, 11);
    EXPECT_DOUBLE_EQ(r.margin, 0.1);
    ExpectClearPath(*world, r, kStart, kGoal, kRadius + r.margin - 1e-9);
    // Round the wall's end at x = 3.8: at least 2 * 7.8 m + the 8 m rise, roughly.
    EXPECT_GT(r.length, 16.0);
    EXPECT_GE(r.attempts, 1);
    EXPECT_GT(r.samples, 0);
  }
}

TEST(GlobalPlanner, AClearSegmentNeedsNoPlanner) {
  const auto world = Room();
  const GlobalPlanner planner(world, Settings("rrtstar"));
  const PlanResult r = planner.Plan(Vec2(-4, 2), Vec2(4, 3), kRadius, 1);
  ASSERT_TRUE(r.solved);
  EXPECT_EQ(r.attempts, 0);
  EXPECT_EQ(r.path, (std::vector<Vec2>{Vec2(-4, 2), Vec2(4, 3)}));
}

TEST(GlobalPlanner, TheMarginIsRelaxedOnlyWhenTheGoalIsCloserToAWall) {
  const auto world = Room();
  const GlobalPlanner planner(world, Settings("rrtconnect"));
  // 0.37 m from the left wall (x = -5): a 0.3 m disc fits with 0.05 m of margin, not 0.1.
  const Vec2 goal(-4.63, 4.0);
  const PlanResult r = planner.Plan(kStart, goal, kRadius, 3);
  EXPECT_DOUBLE_EQ(r.margin, 0.05);
  ExpectClearPath(*world, r, kStart, goal, kRadius + 0.05 - 1e-9);
}

TEST(GlobalPlanner, NoPathToAnEnclosedGoal) {
  const auto world = std::make_shared<CollisionWorld>(crowdsim::testing::MakeRoom(
      {Rect::FromCorners(1.0, 1.0, 4.0, 1.2), Rect::FromCorners(1.0, 3.8, 4.0, 4.0),
       Rect::FromCorners(1.0, 1.2, 1.2, 3.8), Rect::FromCorners(3.8, 1.2, 4.0, 3.8)}));
  PlanSettings s = Settings("rrtconnect", 200);
  s.plan_attempts = 2;
  const GlobalPlanner planner(world, s);
  const PlanResult r = planner.Plan(kStart, Vec2(2.5, 2.5), kRadius, 5);
  EXPECT_FALSE(r.solved);
  EXPECT_TRUE(r.path.empty());
  // Three margins (0.1, 0.05, 0) x two attempts (200, 400 samples), each stopped by its budget.
  EXPECT_EQ(r.attempts, 6);
  EXPECT_GE(r.samples, 3 * (200 + 400));
  EXPECT_LE(r.samples, 3 * (200 + 400) + 6 * 2);
}

TEST(GlobalPlanner, AnUnknownPlannerIsAnError) {
  try {
    const GlobalPlanner planner(Room(), Settings("rrt*"));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("valid planners: rrtstar, "), std::string::npos)
        << e.what();
  }
}

TEST(GlobalPlanner, TheSameSeedGivesTheSamePathInAnyThread) {
  const auto world = Room();
  for (const PlannerInfo& info : Planners()) {
    if (!info.deterministic) continue;
    SCOPED_TRACE(info.name);
    const GlobalPlanner planner(world, Settings(info.name, 600));
    const PlanResult reference = planner.Plan(kStart, kGoal, kRadius, 99);
    ASSERT_TRUE(reference.solved);
    EXPECT_EQ(planner.Plan(kStart, kGoal, kRadius, 99).path, reference.path);
    // Two threads at once, one sharing this planner, one with its own.
    PlanResult a, b;
    std::thread ta([&] { a = planner.Plan(kStart, kGoal, kRadius, 99); });
    std::thread tb([&] {
      const GlobalPlanner own(Room(), Settings(info.name, 600));
      b = own.Plan(kStart, kGoal, kRadius, 99);
    });
    ta.join();
    tb.join();
    EXPECT_EQ(a.path, reference.path);
    EXPECT_EQ(b.path, reference.path);
    EXPECT_EQ(a.samples, reference.samples);
    EXPECT_EQ(b.samples, reference.samples);
  }
}

TEST(GlobalPlanner, TheSeedIsUsed) {
  const auto world = Room();
  const GlobalPlanner planner(world, Settings("rrtstar", 600));
  const PlanResult reference = planner.Plan(kStart, kGoal, kRadius, 1);
  bool differs = false;
  for (std::uint64_t seed = 2; seed < 6 && !differs; ++seed) {
    differs = planner.Plan(kStart, kGoal, kRadius, seed).path != reference.path;
  }
  EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace crowdsim::ompl_planner
