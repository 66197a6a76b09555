// Non-holonomic robots in episodes: heading as state, body-frame sensors, refusals, suite keys.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "scripted.h"
#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

constexpr double kPi = std::numbers::pi;

/// Returns one (linear, angular) command every step.
class CommandPolicy final : public Policy {
 public:
  CommandPolicy(double linear, double angular) : linear_(linear), angular_(angular) {}
  PolicyNeeds Needs() const override {
    PolicyNeeds needs;
    needs.non_holonomic = NonHolonomicDrive::kCommands;
    return needs;
  }
  Action Decide(const Observation& obs) override {
    last = obs;
    return Action::Command(linear_, angular_);
  }
  Observation last;

 private:
  double linear_, angular_;
};

RobotKinematics Unicycle() {
  RobotKinematics k;
  k.model = KinematicsModel::kUnicycle;
  return k;
}

TEST(KinematicsEpisode, UnicycleStepsFollowCrowdNavsFormulaAndRecordHeading) {
  Scenario sc = testing::MakeScenario(testing::MakeMap({}), Vec2(0, -4), Vec2(0, 4));
  CommandPolicy robot(0.5, 1.0);
  Episode ep(sc, SimConfig{}, EpisodeAgents{&robot, {}, {}, Unicycle()}, true);
  // Starts facing its goal (CrowdNav: pi/2).
  EXPECT_DOUBLE_EQ(ep.robot().heading, kPi / 2);
  ep.Step();
  ep.Step();
  const double theta = kPi / 2 + 2 * 0.25;  // turned twice by 1 rad/s x 0.25 s
  EXPECT_NEAR(ep.robot().heading, theta, 1e-12);
  const Vec2 expected = Vec2(0, -4) +
                        0.5 * 0.25 * Vec2(std::cos(kPi / 2 + 0.25), std::sin(kPi / 2 + 0.25)) +
                        0.5 * 0.25 * Vec2(std::cos(theta), std::sin(theta));
  EXPECT_NEAR((ep.robot().position - expected).norm(), 0.0, 1e-12);
  ASSERT_EQ(ep.result().trajectory.size(), 3u);
  EXPECT_NEAR(ep.result().trajectory.back().robot.heading, theta, 1e-12);
  // The observation the policy gets carries the executed command and a body frame.
  ep.Step();
  EXPECT_DOUBLE_EQ(robot.last.linear, 0.5);
  EXPECT_DOUBLE_EQ(robot.last.angular, 1.0);
  EXPECT_NEAR(robot.last.frame.heading, theta, 1e-12);
}

TEST(KinematicsEpisode, ALidarFacingAwayFromTheGoalSeesBehindTheGoalNotTheGoalSide) {
  PluginRegistry registry({testing::PluginDir()});
  const LoadedPlugin& lidar = registry.Load("lidar2d", PluginKind::kSensor);
  Params params = Params::Defaults(lidar.schema);
  params.Set("beams", std::int64_t{45});
  params.Set("fov_deg", 180.0);
  params.Set("max_range", 5.0);
  const auto sensor = registry.MakeSensor(lidar, params);
  // A wall 2 m on the goal side (above), another 3 m behind (below): the robot faces down.
  Scenario sc = testing::MakeScenario(
      testing::MakeMap({Rect::FromCorners(-3, 2, 3, 2.2), Rect::FromCorners(-3, -3.2, 3, -3)}),
      Vec2(0, 0), Vec2(4, 4));
  sc.robot_heading = -kPi / 2;
  for (const bool unicycle : {true, false}) {
    CommandPolicy robot(0.0, 0.0);
    testing::GoStraightPolicy holonomic;
    EpisodeAgents agents{unicycle ? static_cast<Policy*>(&robot) : &holonomic,
                         {},
                         {{"lidar2d", sensor.get()}},
                         unicycle ? Unicycle() : RobotKinematics{}};
    Episode ep(sc, SimConfig{}, agents);
    const Observation& obs = ep.ObserveRobot();
    const SensorReading& r = obs.readings.front();
    double nearest = kInfinity;
    double nearest_y = 0.0;
    for (size_t b = 0; b < r.ranges.size(); ++b) {
      if (r.ranges[b] < nearest) {
        nearest = r.ranges[b];
        nearest_y =
            obs.frame
                .VectorToWorld(Vec2(std::cos(r.angles[b]), std::sin(r.angles[b])) * r.ranges[b])
                .y();
      }
    }
    if (unicycle) {
      EXPECT_NEAR(obs.frame.heading, -kPi / 2, 1e-12);
      EXPECT_NEAR(nearest, 3.0, 1e-9);  // the wall below, straight ahead
      EXPECT_LT(nearest_y, 0.0);
      // No beam reaches the goal side (y > 0) at all.
      for (size_t b = 0; b < r.ranges.size(); ++b) {
        const Vec2 dir =
            obs.frame.VectorToWorld(Vec2(std::cos(r.angles[b]), std::sin(r.angles[b])));
        EXPECT_LE(dir.y(), 1e-9) << "beam " << b;
      }
    } else {
      // The holonomic robot's frame faces its goal: the wall above is the nearest.
      EXPECT_NEAR(obs.frame.heading, kPi / 4, 1e-12);
      EXPECT_GT(nearest_y, 0.0);
    }
  }
}

TEST(KinematicsEpisode, AVelocityOnlyPolicyIsRefusedUnlessTracked) {
  const Scenario sc = testing::MakeScenario(testing::MakeMap({}), Vec2(0, -4), Vec2(0, 4));
  testing::GoStraightPolicy velocity_only;
  RobotKinematics k = Unicycle();
  try {
    Episode ep(sc, SimConfig{}, EpisodeAgents{&velocity_only, {}, {}, k});
    FAIL() << "a velocity-only policy drove a unicycle robot";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("returns world velocities only and cannot drive a "
                                         "unicycle robot: add `track_velocity: true`"),
              std::string::npos)
        << e.what();
  }
  k.track_velocity = true;
  Episode ep(sc, SimConfig{}, EpisodeAgents{&velocity_only, {}, {}, k});
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kSuccess);
  // A command on a holonomic robot is a policy_error naming the fix.
  CommandPolicy command(1.0, 0.0);
  Episode holonomic(sc, SimConfig{}, EpisodeAgents{&command, {}, {}, {}});
  holonomic.Step();
  EXPECT_EQ(holonomic.result().status, EpisodeStatus::kPolicyError);
  EXPECT_NE(holonomic.result().error.find("the robot is holonomic"), std::string::npos);
}

class KinematicsSuite : public ::testing::Test {
 protected:
  SuiteLoadResult Load(const std::string& rows) {
    const auto file = dir_.Write("suite.yaml", std::string(kHead) + rows);
    return LoadSuite(file, registry_);
  }
  static std::string All(const SuiteLoadResult& r) {
    std::string s;
    for (const auto& e : r.errors) s += e.Format() + "\n";
    return s;
  }
  static constexpr const char* kHead =
      "name: k\nepisodes: 2\nseed: 1\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "humans: {count: 2, policy: orca}\n";
  testing::TempDir dir_;
  PluginRegistry registry_{{testing::PluginDir(), testing::FixturePluginDir()}};
};

TEST_F(KinematicsSuite, TheDefaultRobotKeepsItsConfigHash) {
  const auto plain = Load("rows:\n  - {label: a, policy: orca}\n");
  const auto named = Load("rows:\n  - {label: a, policy: orca, kinematics: holonomic}\n");
  const auto robot =
      Load("robot: {kinematics: {model: holonomic}}\nrows:\n  - {label: a, policy: orca}\n");
  const auto unicycle = Load("rows:\n  - {label: a, policy: orca, kinematics: unicycle}\n");
  const auto limited = Load(
      "robot: {kinematics: {model: unicycle, accel_max: 1}}\nrows:\n  - {label: a, policy: "
      "orca}\n");
  ASSERT_TRUE(plain.suite && named.suite && robot.suite && unicycle.suite && limited.suite)
      << All(plain) << All(named) << All(robot) << All(unicycle) << All(limited);
  EXPECT_EQ(plain.suite->rows[0].ConfigHash(), named.suite->rows[0].ConfigHash());
  EXPECT_EQ(plain.suite->rows[0].ConfigHash(), robot.suite->rows[0].ConfigHash());
  EXPECT_NE(plain.suite->rows[0].ConfigHash(), unicycle.suite->rows[0].ConfigHash());
  EXPECT_NE(unicycle.suite->rows[0].ConfigHash(), limited.suite->rows[0].ConfigHash());
  EXPECT_EQ(limited.suite->rows[0].kinematics.model, KinematicsModel::kUnicycle);
  EXPECT_DOUBLE_EQ(limited.suite->rows[0].kinematics.accel_max, 1.0);
}

TEST_F(KinematicsSuite, BadValuesAreNamedWithTheValidChoices) {
  const auto r = Load(
      "rows:\n"
      "  - {label: a, policy: orca, kinematics: unicycel}\n"
      "  - {label: b, policy: orca, kinematics: {model: unicycle, accel_max: 0}}\n"
      "  - {label: c, policy: orca, kinematics: {model: diff_drive, angular_speed_max: -1}}\n"
      "  - {label: d, policy: orca, kinematics: {model: holonomic, angular_accel_max: 2}}\n"
      "  - {label: e, policy: orca, kinematics: {accel_max: 2}}\n"
      "  - {label: f, policy: orca, kinematics: {model: unicycle, acel_max: 2}}\n");
  const std::string all = All(r);
  EXPECT_NE(all.find(":7:42: rows[0].kinematics: value 'unicycel' is not valid; valid: "
                     "holonomic, unicycle, diff_drive; did you mean 'unicycle'?"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("rows[1].kinematics.accel_max: value 0 is out of range; valid: (0, 1e+06]"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("rows[2].kinematics.angular_speed_max: value -1 is out of range"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("rows[3].kinematics.angular_accel_max: 'angular_accel_max' is for a unicycle "
                     "or diff_drive robot"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("rows[4].kinematics.model: missing key 'model'"), std::string::npos) << all;
  EXPECT_NE(all.find("rows[5].kinematics.acel_max: unknown key 'acel_max'"), std::string::npos)
      << all;
}

TEST_F(KinematicsSuite, AVelocityOnlyPluginIsRefusedBeforeTheFirstEpisode) {
  const std::string plugin = (testing::FixturePluginDir() / "crowdsim_throwing_policy.so").string();
  const auto file =
      dir_.Write("refused.yaml", std::string(kHead) + "rows:\n  - {label: a, policy: " + plugin +
                                     ", params: {good_episodes: 1000}, kinematics: unicycle}\n");
  const std::string exe = (testing::BinaryDir() / "bin" / "crowdsim-bench").string();
  const auto [status, out] = testing::Shell(exe + " run " + file.string() + " --out " +
                                            (dir_.path() / "out").string() + " --quiet");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("returns world velocities only and cannot drive a unicycle robot: add "
                     "`track_velocity: true` to the row's kinematics"),
            std::string::npos)
      << out;
  EXPECT_FALSE(std::filesystem::exists(dir_.path() / "out" / "episodes.csv")) << out;
}

}  // namespace
}  // namespace crowdsim
