// The 16-action local planner: the action set's shape, the predicted distance, and the
// choice (the preferred velocity when free, a safe detour from a person, never into a wall).
#include "action_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scripted.h"

namespace crowdsim::ompl_planner {
namespace {

using orca::OrcaAgent;

TEST(ActionSet, TwoSpeedsTimesEightDirectionsFromThePreferredOne) {
  const std::vector<Vec2> actions = ActionSet(Vec2(0.0, 0.4), 1.0);
  ASSERT_EQ(actions.size(), 16u);
  EXPECT_NEAR((actions[0] - Vec2(0.0, 1.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((actions[2] - Vec2(-1.0, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((actions[8] - Vec2(0.0, 0.5)).norm(), 0.0, 1e-12);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(actions[i].norm(), 1.0, 1e-12);
  for (int i = 8; i < 16; ++i) EXPECT_NEAR(actions[i].norm(), 0.5, 1e-12);
}

TEST(ActionSet, PredictedDistanceIsTheClosestApproachWithinTheHorizon) {
  const OrcaAgent person{Vec2(4.0, 0.0), Vec2(-1.0, 0.0), 0.3};
  // Head-on at 2 m/s closing speed: they meet at t = 2 s.
  EXPECT_NEAR(PredictedDistance(Vec2::Zero(), Vec2(1.0, 0.0), 0.3, person, 1.0), 2.0 - 0.6, 1e-12);
  EXPECT_NEAR(PredictedDistance(Vec2::Zero(), Vec2(1.0, 0.0), 0.3, person, 3.0), -0.6, 1e-12);
}

TEST(ActionSet, KeepsThePreferredVelocityWhenNobodyIsNear) {
  const CollisionWorld world(crowdsim::testing::MakeRoom());
  const Vec2 pref(0.6, 0.8);
  EXPECT_EQ(ChooseAction(Vec2::Zero(), pref, {}, world, ActionSetParams{}), pref);
}

TEST(ActionSet, StepsAsideFromAPersonComingHeadOn) {
  const CollisionWorld world(crowdsim::testing::MakeRoom());
  const std::vector<OrcaAgent> people = {{Vec2(1.5, 0.0), Vec2(-1.0, 0.0), 0.3}};
  ActionSetParams params;
  const Vec2 v = ChooseAction(Vec2::Zero(), Vec2(1.0, 0.0), people, world, params);
  EXPECT_NE(v, Vec2(1.0, 0.0));
  EXPECT_GE(PredictedDistance(Vec2::Zero(), v, params.radius, people[0], params.horizon),
            params.clearance);
}

TEST(ActionSet, NeverStepsIntoARectangle) {
  const CollisionWorld world(
      crowdsim::testing::MakeRoom({Rect::FromCorners(0.45, -2.0, 1.0, 2.0)}));
  // Preferred velocity straight into a wall 0.15 m ahead of the robot's surface.
  const ActionSetParams params;
  const Vec2 v = ChooseAction(Vec2::Zero(), Vec2(1.0, 0.0), {}, world, params);
  EXPECT_EQ(world.SweepDisc(Vec2::Zero(), v * params.time_step, params.radius).fraction, kInfinity);
  EXPECT_GT(v.x(), 0.0);  // the slow straight action still fits: 0.125 m < 0.15 m
}

}  // namespace
}  // namespace crowdsim::ompl_planner
