// The headed social force model: each force and the torque against their closed forms by hand,
// the loaded plugin turning round to its goal and never entering a rectangle, and a suite of
// hsfm people giving the same episodes on any number of threads.
#include "hsfm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "suite_runs.h"
#include "temp_dir.h"
#include "test_paths.h"
#include "walk_scene.h"
#include "walking/contact.h"

namespace crowdsim::hsfm {
namespace {

// Two people of radius 0.3 head-on, centres 1 m apart (i at +x of j): no contact, so only
// A exp((0.6 - 1)/0.08) = 2000 exp(-5) = 13.4759 N along +x, whatever their velocities.
TEST(Hsfm, TwoPeopleHeadOnRepelByTheExponential) {
  const Constants c;
  const Vec2 f = PersonForce(Vec2(1.0, 0.0), 0.6, Vec2(-1.0, 0.0), Vec2(1.0, 0.0), c);
  EXPECT_NEAR(f.x(), 2000.0 * std::exp(-5.0), 1e-9);
  EXPECT_NEAR(f.x(), 13.475894, 1e-6);
  EXPECT_EQ(f.y(), 0.0);
}

// Overlapping by 0.1 m (d = 0.5): A exp(0.1/0.08) + k 0.1 = 2000 exp(1.25) + 12000 along n;
// j passes at 1 m/s along +y relative to i, t = (0, 1): friction κ 0.1 x 1 = 24000 N along +y.
TEST(Hsfm, OverlappingPeoplePushAndRub) {
  const Constants c;
  const Vec2 f = PersonForce(Vec2(0.5, 0.0), 0.6, Vec2::Zero(), Vec2(0.0, 1.0), c);
  EXPECT_NEAR(f.x(), 2000.0 * std::exp(1.25) + 12000.0, 1e-6);
  EXPECT_NEAR(f.y(), 24000.0, 1e-6);
}

// A wall 0.4 m away from a person of radius 0.3: A_w exp(-0.1/0.08) = 2000 exp(-1.25) N
// straight away from it. At 0.25 m it overlaps by 0.05 m: + k 0.05 = 6000 N, and walking along
// the wall at 1 m/s (v · t = 1 with n = (0, 1), t = (-1, 0)) rubs with κ 0.05 = 12000 N against
// the walk.
TEST(Hsfm, WallsPushByTheExponentialAndRubWhenTouched) {
  const Constants c;
  const Vec2 far = WallForce(Vec2(0.0, 0.4), 0.3, Vec2(1.0, 0.0), c);
  EXPECT_NEAR(far.y(), 2000.0 * std::exp(-1.25), 1e-9);
  EXPECT_NEAR(far.y(), 573.0096, 1e-4);
  EXPECT_EQ(far.x(), 0.0);
  const Vec2 near = WallForce(Vec2(0.0, 0.25), 0.3, Vec2(-1.0, 0.0), c);
  EXPECT_NEAR(near.y(), 2000.0 * std::exp(0.625) + 6000.0, 1e-6);
  EXPECT_NEAR(near.x(), 12000.0, 1e-6);
  EXPECT_EQ(walking::NearestPoint(Rect::FromCorners(0, 0, 1, 1), Vec2(2.0, 0.5)), Vec2(1.0, 0.5));
}

// Standing, v_pref 1 m/s: m (v0 e - v) / τ = 75 x 1 / 0.5 = 150 N. Under it the heading 0.5 rad
// off accelerates at -k_λ |f| 0.5 = -0.1 x 150 x 0.5 = -7.5 rad/s^2; turning at 1 rad/s it
// is damped by (1 + α) sqrt(k_λ |f| / α) = 4 sqrt(5) = 8.944 rad/s^2 more.
TEST(Hsfm, TheTorqueIsASpringAndDamperOnTheHeading) {
  const Constants c;
  const Vec2 f0 = DrivingForce(Vec2::Zero(), Vec2(1.0, 0.0), c);
  EXPECT_NEAR(f0.x(), 150.0, 1e-12);
  EXPECT_NEAR(TurnAcceleration(0.5, 0.0, f0.norm(), c), -7.5, 1e-12);
  EXPECT_NEAR(TurnAcceleration(0.5, 1.0, f0.norm(), c), -7.5 - 4.0 * std::sqrt(5.0), 1e-12);
  // Its roots -sqrt(k_λ|f|/α) and -α sqrt(k_λ|f|/α): critically damped never, overshoot never.
  EXPECT_EQ(TurnAcceleration(0.0, 0.0, 0.0, c), 0.0);
}

// A group's centre 1.5 m ahead and 0.3 m to the left: beyond d_f = 1 forward, k1g 1.5/|p| pulls
// forward; within d_o = 0.5 sideways, nothing. 2 m to the right: k2g (-2)/2 = -200 N sideways.
TEST(Hsfm, GroupCohesionActsBeyondItsDistances) {
  const GroupConstants g;
  Body body;  // facing +x
  const Vec2 p(1.5, 0.3);
  const Vec2 u = GroupCohesion(p, body, g);
  EXPECT_NEAR(u.x(), 200.0 * 1.5 / p.norm(), 1e-9);
  EXPECT_EQ(u.y(), 0.0);
  const Vec2 right = GroupCohesion(Vec2(0.0, -2.0), body, g);
  EXPECT_EQ(right.x(), 0.0);
  EXPECT_NEAR(right.y(), -200.0, 1e-12);
}

// The body's inputs: forward the total force along the heading; sideways k_o fe · left less
// k_d v_o; one 0.01 s step from rest with f0 = (150, 0), fe = (0, 100), facing +x: forward
// 150 x 0.01 / 75 = 0.02 m/s, sideways 100 x 0.01 / 75 = 0.01333 m/s; the heading turns left.
TEST(Hsfm, OneStepDrivesForwardPushesSidewaysAndTurnsToTheForce) {
  const Constants c;
  Body body;
  Advance(&body, Vec2(150.0, 0.0), Vec2(0.0, 100.0), Vec2::Zero(), 0.01, 10.0, c);
  EXPECT_NEAR(body.forward, 0.02, 1e-12);
  EXPECT_NEAR(body.sideways, 100.0 * 0.01 / 75.0, 1e-12);
  EXPECT_GT(body.omega, 0.0);  // towards atan2(100, 150), left of +x
  // Sideways motion is damped: with no force, v_o falls by k_d h / m = 500 x 0.01 / 75 a step.
  Body sliding;
  sliding.sideways = 1.0;
  Advance(&sliding, Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), 0.01, 10.0, c);
  EXPECT_NEAR(sliding.sideways, 1.0 - 500.0 * 0.01 / 75.0, 1e-12);
}

// The torque turns a heading towards the force, whatever side it starts on, and settles there
// without swinging past (its roots are real): 4 s of 0.025 s steps under 150 N along +y.
TEST(Hsfm, TheHeadingTurnsToTheForceDirection) {
  const Constants c;
  for (const double start : {-2.5, -1.0, 0.0, 2.0, 3.1}) {
    Body body;
    body.theta = start;
    const double first = std::remainder(start - M_PI / 2, 2 * M_PI);
    for (int k = 0; k < 160; ++k) {
      Advance(&body, Vec2(0.0, 150.0), Vec2::Zero(), Vec2::Zero(), 0.025, 0.0, c);
      const double error = std::remainder(body.theta - M_PI / 2, 2 * M_PI);
      ASSERT_GE(error * first, -1e-9) << "swung past, from " << start << " at step " << k;
    }
    EXPECT_NEAR(body.theta, M_PI / 2, 1e-3) << "from " << start;
    EXPECT_NEAR(body.omega, 0.0, 1e-2) << "from " << start;
  }
}

// A person standing with its back to its goal 5 m away (θ = π): the driving force turns it
// round within 2 s, it walks facing its goal, and it stops on its goal (the desired velocity
// is CrowdNav's: v_pref towards the goal, goal - position within 1 m).
TEST(Hsfm, APersonStandingWithItsBackToItsGoalTurnsAndWalksThere) {
  const Constants c;
  const Vec2 goal(5.0, 0.0);
  Body body;
  body.theta = M_PI;
  double turned = -1.0, facing_at_3s = 0.0;
  for (int k = 0; k < 400; ++k) {
    const Vec2 d = goal - body.position;
    const Vec2 desired = d.norm() > 1.0 ? Vec2(d / d.norm()) : d;
    Advance(&body, DrivingForce(body.Velocity(), desired, c), Vec2::Zero(), Vec2::Zero(), 0.025,
            1.0, c);
    if (turned < 0.0 && std::cos(body.theta) > 0.99) turned = (k + 1) * 0.025;
    if (k + 1 == 120) facing_at_3s = std::cos(body.theta);
  }
  EXPECT_GT(turned, 0.0);
  EXPECT_LT(turned, 2.0);
  EXPECT_NEAR(body.position.x(), 5.0, 0.05);
  EXPECT_NEAR(body.position.y(), 0.0, 0.05);
  EXPECT_GT(facing_at_3s, 0.999);
  EXPECT_LT(body.Velocity().norm(), 0.05);  // settling: the heading swings round as it overshoots
}

// Through the loaded plugin: a person backing slowly away from its goal 5 m ahead starts
// facing its velocity, away from the goal, turns round and arrives, never faster than v_pref.
TEST(Hsfm, ThePluginTurnsAPersonRoundToItsGoal) {
  PluginRegistry registry({crowdsim::testing::PluginDir()});
  const LoadedPlugin& plugin = registry.Load("hsfm", PluginKind::kPolicy);
  AgentState self;
  self.velocity = Vec2(-0.1, 0.0);
  self.goal = Vec2(5.0, 0.0);
  int arrived = -1;
  testing::Walk(plugin, registry, Params::Defaults(plugin.schema), nullptr, self, 60,
                [&](int step, const Vec2& v, const AgentState& s) {
                  ASSERT_LE(v.norm(), 1.0 + 1e-9);
                  if (arrived < 0 && (s.goal - s.position).norm() < 0.1) arrived = step;
                });
  EXPECT_GE(arrived, 20) << "5 m at <= 1 m/s takes 20 steps";
  EXPECT_LT(arrived, 50);
}

// Property: over random maps, starts and goals, an hsfm person never comes closer to a
// rectangle than its radius. A third of the scenes turn the walls' force off (a_wall = 0,
// k_body = 0) and the guidance too, so people walk straight into rectangles between them and
// their goals and only the slide along edges keeps them out.
TEST(Hsfm, APersonNeverWalksIntoARectangle) {
  PluginRegistry registry({crowdsim::testing::PluginDir()});
  const LoadedPlugin& plugin = registry.Load("hsfm", PluginKind::kPolicy);
  std::mt19937 rng(11);
  int steps_checked = 0, touching = 0;
  for (int scene = 0; scene < 60; ++scene) {
    Params params = Params::Defaults(plugin.schema);
    params.Set("guidance", scene % 3 == 0);
    if (scene % 3 == 2) {
      params.Set("a_wall", 0.0);
      params.Set("k_body", 0.0);
    }
    const testing::WalkScene drawn = testing::RandomWalkScene(rng);
    const StaticMap& map = drawn.map;
    const AgentState& self = drawn.self;
    testing::Walk(plugin, registry, params, &map, self, 120,
                  [&](int step, const Vec2& v, const AgentState& s) {
                    ASSERT_LE(v.norm(), 1.0 + 1e-9);
                    for (const Rect& rect : map.rectangles) {
                      const double gap =
                          (s.position - walking::NearestPoint(rect, s.position)).norm();
                      ASSERT_GE(gap, self.radius - 1e-9) << "scene " << scene << " step " << step;
                      touching += gap < self.radius + 0.02;
                    }
                    ++steps_checked;
                  });
  }
  EXPECT_EQ(steps_checked, 60 * 120);
  EXPECT_GT(touching, 100) << "the scenes must bring people against rectangles";
}

// Hsfm people in a suite: the same episodes on one thread and on two.
TEST(Hsfm, ASuiteOfHsfmPeopleGivesTheSameEpisodesOnAnyThreads) {
  testing::TempDir dir;
  const auto file =
      dir.Write("hsfm.yaml",
                "name: hsfm\nepisodes: 6\nseed: 4\nworld: {source: random_rect, obstacles: 3}\n"
                "humans: {count: 5, policy: hsfm, groups: {share: 0.6, size: 2}}\n"
                "robot: {sensors: [person]}\n"
                "rows:\n  - {label: orca, policy: orca}\n  - {label: hsfm, policy: hsfm}\n");
  const auto runs = testing::RunOnOneAndTwoThreads(file, dir.path());
  ASSERT_EQ(runs[0].rows, 2u);
  EXPECT_EQ(runs[0].episodes, runs[1].episodes);
}

}  // namespace
}  // namespace crowdsim::hsfm
