// The social navigation metrics on hand-built trajectories with hand-computed values.
#include "crowdsim/bench/social_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace crowdsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDt = 0.25;

AgentState Agent(double x, double y, double vx = 0.0, double vy = 0.0, double heading = 0.0) {
  AgentState a;
  a.position = Vec2(x, y);
  a.velocity = Vec2(vx, vy);
  a.heading = heading;
  a.radius = 0.3;
  return a;
}

AgentState Robot(double x, double y, double vx, double vy, double heading = 0.0) {
  AgentState r = Agent(x, y, vx, vy, heading);
  r.goal = Vec2(10.0, 0.0);
  return r;
}

TEST(SocialMetrics, ConstantAccelerationHasItsAccelerationAndNoJerk) {
  // From rest along x at 0.4 m/s^2: v_k = 0.4 k dt, x_k = 0.2 (k dt)^2, facing the goal.
  SocialMetricsAccumulator m(kDt, /*holonomic=*/false, 0.2);
  for (int k = 0; k <= 8; ++k) {
    const double t = k * kDt;
    m.Observe(Robot(0.2 * t * t, 0.0, 0.4 * t, 0.0), {});
  }
  const SocialMetrics s = m.Finish(false, 10.0);
  EXPECT_NEAR(s.accel_mean, 0.4, 1e-12);
  EXPECT_NEAR(s.accel_max, 0.4, 1e-12);
  EXPECT_NEAR(s.jerk_mean, 0.0, 1e-9);
  EXPECT_NEAR(s.jerk_max, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.angular_accel_max, 0.0);
  EXPECT_DOUBLE_EQ(s.path_irregularity, 0.0);  // it always faces its goal
  EXPECT_DOUBLE_EQ(s.freezing_time, 0.0);      // moving from the first step
  EXPECT_DOUBLE_EQ(s.spl, 0.0);                // no success
}

TEST(SocialMetrics, AStepInSpeedIsOneAccelerationAndTwoJerks) {
  // 0, 1, 1, 1 m/s: a = 4, 0, 0 m/s^2; jerk |0 - 4| / dt = 16, then 0.
  SocialMetricsAccumulator m(kDt, true, 0.2);
  const double v[] = {0.0, 1.0, 1.0, 1.0};
  double x = 0.0;
  for (double vk : v) {
    x += vk * kDt;
    m.Observe(Robot(x, 0.0, vk, 0.0), {});
  }
  const SocialMetrics s = m.Finish(false, 10.0);
  EXPECT_NEAR(s.accel_mean, 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.accel_max, 4.0, 1e-12);
  EXPECT_NEAR(s.jerk_mean, 8.0, 1e-12);
  EXPECT_NEAR(s.jerk_max, 16.0, 1e-12);
  EXPECT_TRUE(std::isnan(s.angular_accel_mean));  // a holonomic robot has no heading
  EXPECT_TRUE(std::isnan(s.angular_jerk_max));
}

TEST(SocialMetrics, TurningAtConstantRateHasNoAngularAcceleration) {
  // omega = 0.4 rad/s from the first step: alpha = 1.6 rad/s^2 once, then 0; jerk 6.4 once.
  SocialMetricsAccumulator m(kDt, false, 0.2);
  for (int k = 0; k <= 4; ++k) m.Observe(Robot(0.0, 0.0, 0.0, 0.0, 0.1 * k), {});
  const SocialMetrics s = m.Finish(false, 10.0);
  EXPECT_NEAR(s.angular_accel_max, 1.6, 1e-12);
  EXPECT_NEAR(s.angular_accel_mean, 1.6 / 4, 1e-12);
  EXPECT_NEAR(s.angular_jerk_max, 6.4, 1e-12);
  // Turning at 0.4 rad/s is not standing still (HuNavSim: below 0.02 rad/s).
  EXPECT_DOUBLE_EQ(s.freezing_time, 0.0);
}

TEST(SocialMetrics, ARobotParkedOneMetreFromAStandingPersonForTenSeconds) {
  SocialMetricsAccumulator m(kDt, false, 0.2);
  const std::vector<AgentState> person = {Agent(1.0, 0.0)};
  for (int k = 0; k <= 40; ++k) m.Observe(Robot(0.0, 0.0, 0.0, 0.0), person);
  const SocialMetrics s = m.Finish(false, 10.0);
  EXPECT_DOUBLE_EQ(s.personal_share * 40 * kDt, 10.0);  // 10 s inside the personal zone
  EXPECT_DOUBLE_EQ(s.intimate_share, 0.0);
  EXPECT_DOUBLE_EQ(s.personal_intrusions, 0.0);  // inside from time 0: nobody entered
  EXPECT_DOUBLE_EQ(s.freezing_time, 10.0);       // still, 10 m from its goal
  EXPECT_DOUBLE_EQ(s.min_ttc, 5.0);  // nobody moves: no collision within the 5 s horizon
}

TEST(SocialMetrics, APersonWalkingUpCountsOneIntrusionAndItsTimeToCollision) {
  // A person from x = 3 towards the still robot at 1 m/s (d = 3 - t between centres): within
  // 1.2 m at t = 2, 2.25, .., 3 (5 of 12 steps, one entry), within 0.45 m at t = 2.75, 3.
  SocialMetricsAccumulator m(kDt, false, 0.2);
  for (int k = 0; k <= 12; ++k) {
    const double t = k * kDt;
    const std::vector<AgentState> person = {Agent(3.0 - t, 0.0, -1.0, 0.0)};
    m.Observe(Robot(0.0, 0.0, 0.0, 0.0), person);
  }
  const SocialMetrics s = m.Finish(false, 10.0);
  EXPECT_DOUBLE_EQ(s.personal_intrusions, 1.0);
  EXPECT_NEAR(s.personal_share, 5.0 / 12.0, 1e-12);
  EXPECT_NEAR(s.intimate_share, 2.0 / 12.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.min_ttc, 0.0);  // the discs overlap from t = 2.5
}

TEST(SocialMetrics, TimeToCollisionBeforeTheyMeet) {
  // The same approach seen only at time 0: surface gap 2.4 m closing at 1 m/s.
  SocialMetricsAccumulator m(kDt, false, 0.2);
  const std::vector<AgentState> person = {Agent(3.0, 0.0, -1.0, 0.0)};
  m.Observe(Robot(0.0, 0.0, 0.0, 0.0), person);
  EXPECT_NEAR(m.Finish(false, 10.0).min_ttc, 2.4, 1e-12);
  // A 5.4 m gap closing at 1 m/s is 5.4 s away: beyond the 5 s horizon.
  SocialMetricsAccumulator far(kDt, false, 0.2);
  const std::vector<AgentState> distant = {Agent(6.0, 0.0, -1.0, 0.0)};
  far.Observe(Robot(0.0, 0.0, 0.0, 0.0), distant);
  EXPECT_DOUBLE_EQ(far.Finish(false, 10.0).min_ttc, 5.0);
}

TEST(SocialMetrics, TimeToCollisionOfTwoDiscs) {
  EXPECT_NEAR(TimeToCollision(Agent(0, 0), Agent(3, 0, -1, 0)), 2.4, 1e-12);
  EXPECT_NEAR(TimeToCollision(Agent(0, 0, 0.5, 0), Agent(3, 0, -1, 0)), 1.6, 1e-12);
  // Passing 1 m apart: 0.6 m of radii never touch.
  EXPECT_EQ(TimeToCollision(Agent(0, 0), Agent(3, 1, -1, 0)),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(TimeToCollision(Agent(0, 0), Agent(3, 0, 1, 0)),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(TimeToCollision(Agent(0, 0), Agent(0.5, 0)), 0.0);
}

TEST(SocialMetrics, PathIrregularityIsTheAngleAwayFromTheGoalPerMetre) {
  // Five states heading +y while the goal lies along +x, over 1 m: 5 (pi/2) / 1 rad/m.
  SocialMetricsAccumulator m(kDt, false, 0.2);
  for (int k = 0; k <= 4; ++k) m.Observe(Robot(0.25 * k, 0.0, 1.0, 0.0, kPi / 2), {});
  EXPECT_NEAR(m.Finish(false, 10.0).path_irregularity, 5 * (kPi / 2), 1e-12);
}

TEST(SocialMetrics, SplIsSuccessWeightedShortestOverTravelled) {
  SocialMetricsAccumulator m(kDt, true, 0.2);
  // 12 m travelled in 12 steps of 1 m.
  for (int k = 0; k <= 12; ++k) m.Observe(Robot(k, 0.0, 4.0, 0.0), {});
  EXPECT_NEAR(m.Finish(true, 10.0).spl, 10.0 / 12.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.Finish(false, 10.0).spl, 0.0);
  EXPECT_DOUBLE_EQ(m.Finish(true, 10.0).shortest_path, 10.0);
}

TEST(SocialMetrics, StandingAtTheGoalIsNoFreezing) {
  SocialMetricsAccumulator m(kDt, true, 0.2);
  for (int k = 0; k <= 8; ++k) m.Observe(Robot(9.9, 0.0, 0.0, 0.0), {});
  EXPECT_DOUBLE_EQ(m.Finish(true, 9.9).freezing_time, 0.0);
}

// A pair standing at (0, +-1): its space is the circle of 1 - 0.3 m around (0, 0) inside their
// bodies, reached by the robot's disc (0.3 m) within 1 m. Driving along y = 0 from x = -3 at 1 m/s,
// the robot is in it at x = -0.75 ... 0.75: 7 of 24 steps, one entry; along y = 2 never.
TEST(SocialMetrics, DrivingThroughAPairIsOneGroupIntrusion) {
  AgentState a = Agent(0.0, 1.0), b = Agent(0.0, -1.0);
  a.group = b.group = 0;
  const AgentState pair[] = {a, b};
  for (const double y : {0.0, 2.0}) {
    SocialMetricsAccumulator m(kDt, true, 0.2);
    for (int k = 0; k <= 24; ++k) m.Observe(Robot(-3.0 + k * kDt, y, 1.0, 0.0), pair);
    const SocialMetrics s = m.Finish(false, 10.0);
    EXPECT_DOUBLE_EQ(s.group_intrusions, y == 0.0 ? 1.0 : 0.0);
    EXPECT_DOUBLE_EQ(s.group_share, y == 0.0 ? 7.0 / 24.0 : 0.0);
  }
  // People alone (or a "group" of one) have no group space: not applicable.
  const AgentState alone[] = {Agent(0.0, 1.0), Agent(0.0, -1.0)};
  SocialMetricsAccumulator m(kDt, true, 0.2);
  for (int k = 0; k <= 24; ++k) m.Observe(Robot(-3.0 + k * kDt, 0.0, 1.0, 0.0), alone);
  EXPECT_TRUE(std::isnan(m.Finish(false, 10.0).group_intrusions));
  EXPECT_TRUE(std::isnan(m.Finish(false, 10.0).group_share));
}

TEST(SocialMetrics, TheShortestFreePathGoesAroundAWall) {
  // A wall x in [4.9, 5.1], y in [-2, 2] between (0, 0) and (10, 0); a 0.3 m disc passes its
  // corners 0.3 m off: two tangents to (5 -+ 0.1, 2.3) and the 0.2 m along the top,
  // 2 sqrt(4.9^2 + 2.3^2) + 0.2 = 11.026 m (the 0.1 m route grid is within a few per cent).
  StaticMap map;
  map.bounds = Rect::FromCorners(-5, -5, 15, 5);
  map.rectangles = {Rect::FromCorners(4.9, -2, 5.1, 2)};
  AgentState robot = Robot(0.0, 0.0, 0.0, 0.0);
  const double d = ShortestFreePath(map, robot);
  EXPECT_GT(d, 10.9);
  EXPECT_LT(d, 11.026 * 1.03);
  map.rectangles.clear();
  EXPECT_DOUBLE_EQ(ShortestFreePath(map, robot), 10.0);
}

}  // namespace
}  // namespace crowdsim
