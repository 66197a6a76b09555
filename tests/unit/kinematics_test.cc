// The robot's motion models: CrowdNav's unicycle, the exact arc, limits and turn-then-go tracking.
#include "crowdsim/kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "crowdsim/rng.h"

namespace crowdsim {
namespace {

constexpr double kPi = std::numbers::pi;

RobotKinematics Model(KinematicsModel m) {
  RobotKinematics k;
  k.model = m;
  return k;
}

RobotMotion Facing(double heading) {
  RobotMotion motion;
  motion.heading = heading;
  return motion;
}

TEST(Kinematics, UnicycleTurnsFirstThenMovesAlongTheNewHeading) {
  // CrowdNav's ActionRot(v = 0.5, r = pi/6) from theta = pi/2, dt = 0.25: theta' = 2 pi/3,
  // p' - p = 0.5 (cos 2pi/3, sin 2pi/3) 0.25 = (-0.0625, 0.108253).
  const double dt = 0.25;
  const ExecutedMove m = ExecuteAction(Model(KinematicsModel::kUnicycle), 1.0, Facing(kPi / 2),
                                       Action::Command(0.5, (kPi / 6) / dt), dt);
  EXPECT_NEAR(m.heading, 2 * kPi / 3, 1e-12);
  EXPECT_NEAR(m.velocity.x() * dt, -0.0625, 1e-12);
  EXPECT_NEAR(m.velocity.y() * dt, 0.10825317547305482, 1e-12);
  EXPECT_DOUBLE_EQ(m.linear, 0.5);
  EXPECT_NEAR(m.angular, (kPi / 6) / dt, 1e-12);
}

TEST(Kinematics, UnicycleWithoutTurnIsHolonomicAlongItsHeading) {
  const ExecutedMove m = ExecuteAction(Model(KinematicsModel::kUnicycle), 1.0, Facing(0.0),
                                       Action::Command(1.0, 0.0), 0.25);
  EXPECT_DOUBLE_EQ(m.velocity.x(), 1.0);
  EXPECT_DOUBLE_EQ(m.velocity.y(), 0.0);
  EXPECT_DOUBLE_EQ(m.heading, 0.0);
}

TEST(Kinematics, DiffDriveFollowsTheExactArc) {
  // v = 1 m/s, w = pi rad/s for 0.5 s from heading 0 at the origin: a quarter circle of radius
  // 1/pi ends at (1/pi, 1/pi), facing pi/2.
  const double dt = 0.5;
  const ExecutedMove m = ExecuteAction(Model(KinematicsModel::kDiffDrive), 1.0, Facing(0.0),
                                       Action::Command(1.0, kPi), dt);
  EXPECT_NEAR(m.velocity.x() * dt, 1.0 / kPi, 1e-12);
  EXPECT_NEAR(m.velocity.y() * dt, 1.0 / kPi, 1e-12);
  EXPECT_NEAR(m.heading, kPi / 2, 1e-12);
}

TEST(Kinematics, LimitsAreNeverExceededOverRandomCommands) {
  for (KinematicsModel model : {KinematicsModel::kUnicycle, KinematicsModel::kDiffDrive}) {
    RobotKinematics k = Model(model);
    k.accel_max = 0.8;
    k.angular_accel_max = 2.0;
    k.angular_speed_max = 1.5;
    const double dt = 0.25;
    const double v_pref = 1.2;
    Rng rng(42);
    RobotMotion motion;
    for (int step = 0; step < 20000; ++step) {
      const Action command = Action::Command(rng.Uniform(-5.0, 5.0), rng.Uniform(-20.0, 20.0));
      const ExecutedMove m = ExecuteAction(k, v_pref, motion, command, dt);
      ASSERT_LE(std::abs(m.linear - motion.linear), k.accel_max * dt * (1 + 1e-12));
      ASSERT_LE(std::abs(m.angular - motion.angular), k.angular_accel_max * dt * (1 + 1e-12));
      ASSERT_LE(std::abs(m.angular), k.angular_speed_max);
      ASSERT_LE(std::abs(m.linear), v_pref);
      // The displacement is never longer than the speed allows (the chord of an arc is shorter).
      ASSERT_LE(m.velocity.norm(), std::abs(m.linear) * (1 + 1e-12));
      motion = RobotMotion{m.velocity, m.heading, m.linear, m.angular};
    }
  }
}

TEST(Kinematics, HolonomicAccelerationClipsTheVelocityChangeAsAVector) {
  RobotKinematics k;
  k.accel_max = 1.0;
  RobotMotion motion;
  motion.velocity = Vec2(1.0, 0.0);
  // Asking for (-1, 0) at 1 m/s^2 over 0.5 s: 0.5 m/s of change towards it.
  const ExecutedMove m = ExecuteAction(k, 1.0, motion, Action(Vec2(-1.0, 0.0)), 0.5);
  EXPECT_DOUBLE_EQ(m.velocity.x(), 0.5);
  EXPECT_DOUBLE_EQ(m.velocity.y(), 0.0);
  Rng rng(7);
  for (int i = 0; i < 10000; ++i) {
    const Action a(Vec2(rng.Uniform(-3, 3), rng.Uniform(-3, 3)));
    const ExecutedMove r = ExecuteAction(k, 1.0, motion, a, 0.25);
    ASSERT_LE((r.velocity - motion.velocity).norm(), 0.25 * (1 + 1e-12));
    motion.velocity = r.velocity;
  }
}

TEST(Kinematics, TrackingTurnsThenGoes) {
  const RobotKinematics k = Model(KinematicsModel::kUnicycle);  // pi rad/s: 45 degrees a step
  const double dt = 0.25;
  // Straight ahead: full speed, no turn.
  Action a = TrackVelocity(k, Facing(0.0), Vec2(0.8, 0.0), dt);
  EXPECT_TRUE(a.command);
  EXPECT_DOUBLE_EQ(a.linear, 0.8);
  EXPECT_DOUBLE_EQ(a.angular, 0.0);
  // 30 degrees left: turns all of it this step, then goes at full speed.
  a = TrackVelocity(k, Facing(0.0), Vec2(std::cos(kPi / 6), std::sin(kPi / 6)), dt);
  EXPECT_NEAR(a.angular * dt, kPi / 6, 1e-12);
  EXPECT_NEAR(a.linear, 1.0, 1e-12);
  // Behind: turns 45 degrees and does not move (135 degrees still to go).
  a = TrackVelocity(k, Facing(0.0), Vec2(-1.0, 0.0), dt);
  EXPECT_NEAR(std::abs(a.angular) * dt, kPi / 4, 1e-12);
  EXPECT_DOUBLE_EQ(a.linear, 0.0);
  // 90 degrees right: 45 this step, then the speed projected on the remaining 45 degrees.
  a = TrackVelocity(k, Facing(0.0), Vec2(0.0, -1.0), dt);
  EXPECT_NEAR(a.angular * dt, -kPi / 4, 1e-12);
  EXPECT_NEAR(a.linear, std::cos(kPi / 4), 1e-12);
  // Stop: no turn.
  a = TrackVelocity(k, Facing(1.0), Vec2::Zero(), dt);
  EXPECT_DOUBLE_EQ(a.linear, 0.0);
  EXPECT_DOUBLE_EQ(a.angular, 0.0);
}

TEST(Kinematics, NamesRoundTripAndAnglesWrap) {
  for (KinematicsModel m :
       {KinematicsModel::kHolonomic, KinematicsModel::kUnicycle, KinematicsModel::kDiffDrive}) {
    KinematicsModel parsed = KinematicsModel::kHolonomic;
    ASSERT_TRUE(ParseKinematicsModel(KinematicsModelName(m), &parsed));
    EXPECT_EQ(parsed, m);
  }
  KinematicsModel unused;
  EXPECT_FALSE(ParseKinematicsModel("unicycel", &unused));
  EXPECT_NEAR(WrapAngle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(WrapAngle(-kPi), kPi);
  EXPECT_DOUBLE_EQ(WrapAngle(0.0), 0.0);
}

}  // namespace
}  // namespace crowdsim
