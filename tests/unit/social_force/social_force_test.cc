// The social force model: each force against its closed form by hand, the gradient against
// finite differences, the loaded plugin never entering a rectangle, and a suite with social
// force people giving the same episodes on any number of threads.
#include "social_force.h"

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

namespace crowdsim::social_force {
namespace {

// Moussaïd et al. 2010's group forces, by hand. A pair 2 m apart: the centre is 1 m away, beyond
// the (2 - 1) / 2 = 0.5 m threshold, so coherence pulls with 2 m/s^2 towards it; the partner lies
// straight ahead (no gaze force) and is farther than 0.5 m (no repulsion).
TEST(SocialForce, AFarPartnerPullsWithTheCoherenceFactor) {
  const GroupConstants g;
  const Vec2 partner[] = {Vec2(2.0, 0.0)};
  const Vec2 f = GroupForce(Vec2::Zero(), Vec2(1.0, 0.0), partner, g);
  EXPECT_NEAR(f.x(), 2.0, 1e-12);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  // Within the threshold (centre 0.4 m away) nothing pulls.
  const Vec2 near[] = {Vec2(0.8, 0.0)};
  EXPECT_NEAR(GroupForce(Vec2::Zero(), Vec2(1.0, 0.0), near, g).norm(), 0.0, 1e-12);
  // Alone: no force.
  EXPECT_EQ(GroupForce(Vec2::Zero(), Vec2(1.0, 0.0), {}, g), Vec2::Zero());
}

// The partner 0.4 m to the left of a member walking along x: closer than 0.5 m, it pushes with
// 1 m/s^2 away (along -y); at 90° it is within the 100° view, so no gaze force.
TEST(SocialForce, AClosePartnerPushesAway) {
  const GroupConstants g;
  const Vec2 partner[] = {Vec2(0.0, 0.4)};
  const Vec2 f = GroupForce(Vec2::Zero(), Vec2(1.0, 0.0), partner, g);
  EXPECT_NEAR(f.x(), 0.0, 1e-12);
  EXPECT_NEAR(f.y(), -1.0, 1e-12);
}

// The partner 0.8 m straight behind: 180° off the walking direction, 80° beyond the 100° view,
// so the gaze force is -3 (80° in rad) e; the centre is 0.4 m away (no pull), no repulsion.
TEST(SocialForce, APartnerBehindTurnsTheGaze) {
  const GroupConstants g;
  const Vec2 partner[] = {Vec2(-0.8, 0.0)};
  const Vec2 f = GroupForce(Vec2::Zero(), Vec2(1.0, 0.0), partner, g);
  EXPECT_NEAR(f.x(), -3.0 * 80.0 * M_PI / 180.0, 1e-9);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
}

// A standing person 1 m away pushes with V0/σ exp(-1/σ) = 7 exp(-10/3) along the line.
TEST(SocialForce, AStandingPersonPushesWithTheCircularGradient) {
  const Constants c;
  const Vec2 f = PedestrianRepulsion(Vec2(1.0, 0.0), Vec2::Zero(), c);
  EXPECT_NEAR(f.x(), 2.1 / 0.3 * std::exp(-1.0 / 0.3), 1e-12);
  EXPECT_NEAR(f.y(), 0.0, 1e-15);
}

// b walks at 0.2 m/s straight at a, 1 m away: s = 0.4 m, b = sqrt(d (d - s)) = sqrt(0.6),
// ∂b/∂x = (2d - s) / (2b) = 1.6 / (2 sqrt(0.6)); force = that x 7 exp(-sqrt(0.6)/0.3).
TEST(SocialForce, APersonComingHeadOnPushesAsTheEllipseSays) {
  const Constants c;
  const Vec2 f = PedestrianRepulsion(Vec2(1.0, 0.0), Vec2(0.2, 0.0), c);
  const double b = std::sqrt(0.6);
  EXPECT_NEAR(f.x(), 1.6 / (2.0 * b) * 7.0 * std::exp(-b / 0.3), 1e-12);
  EXPECT_NEAR(f.x(), 0.546725, 1e-6);
  EXPECT_NEAR(f.y(), 0.0, 1e-15);
  // Walking away, the same person pushes less than one standing.
  EXPECT_LT(PedestrianRepulsion(Vec2(1.0, 0.0), Vec2(-0.2, 0.0), c).x(),
            PedestrianRepulsion(Vec2(1.0, 0.0), Vec2::Zero(), c).x());
}

// -∇V by central differences of V0 exp(-b(r)/σ), at random relative positions and velocities.
TEST(SocialForce, TheRepulsionIsMinusTheGradientOfThePotential) {
  const Constants c;
  auto potential = [&](const Vec2& r, const Vec2& v) {
    const double s = v.norm() * c.step_time;
    const Vec2 next = r - (s > 0 ? Vec2(v / v.norm() * s) : Vec2::Zero());
    const double sum = r.norm() + next.norm();
    return c.v0_ped * std::exp(-0.5 * std::sqrt(sum * sum - s * s) / c.sigma);
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-3.0, 3.0), vel(-1.5, 1.5);
  for (int k = 0; k < 200; ++k) {
    const Vec2 r(pos(rng), pos(rng)), v(vel(rng), vel(rng));
    if (r.norm() < 0.2) continue;
    const Vec2 f = PedestrianRepulsion(r, v, c);
    const double h = 1e-6;
    const Vec2 numeric(-(potential(r + Vec2(h, 0), v) - potential(r - Vec2(h, 0), v)) / (2 * h),
                       -(potential(r + Vec2(0, h), v) - potential(r - Vec2(0, h), v)) / (2 * h));
    EXPECT_NEAR(f.x(), numeric.x(), 1e-6 + 1e-5 * numeric.norm()) << r.transpose();
    EXPECT_NEAR(f.y(), numeric.y(), 1e-6 + 1e-5 * numeric.norm()) << r.transpose();
  }
}

TEST(SocialForce, PeopleBehindWeighHalfAndWallsPushByTheirPotential) {
  const Constants c;
  const Vec2 heading(1.0, 0.0);
  // A force pushing backwards comes from someone ahead: seen. One pushing forwards: behind.
  EXPECT_EQ(ViewWeight(heading, Vec2(-1.0, 0.0), c), 1.0);
  EXPECT_EQ(ViewWeight(heading, Vec2(1.0, 0.0), c), 0.5);
  // 2φ = 200°: a source 95° off the heading is in view, one 105° off is not.
  const double in = 95.0 * M_PI / 180.0, out = 105.0 * M_PI / 180.0;
  EXPECT_EQ(ViewWeight(heading, -Vec2(std::cos(in), std::sin(in)), c), 1.0);
  EXPECT_EQ(ViewWeight(heading, -Vec2(std::cos(out), std::sin(out)), c), 0.5);
  // A wall 0.3 m away: U0/R exp(-0.3/R) = 50 exp(-1.5), pointing away from it.
  const Vec2 w = WallRepulsion(Vec2(0.0, 0.3), c);
  EXPECT_NEAR(w.y(), 50.0 * std::exp(-1.5), 1e-12);
  EXPECT_EQ(w.x(), 0.0);
  EXPECT_EQ(NearestPoint(Rect::FromCorners(0, 0, 1, 1), Vec2(2.0, 0.5)), Vec2(1.0, 0.5));
}

// Property: over random maps, starts and goals, a social force person never comes closer to a
// rectangle than its radius. The forces alone do not promise it, the slide along edges does:
// a third of the scenes turn the walls' force off (u0 = 0) and the guidance too, so people walk
// straight into the rectangles between them and their goals.
TEST(SocialForce, APersonNeverWalksIntoARectangle) {
  PluginRegistry registry({crowdsim::testing::PluginDir()});
  const LoadedPlugin& plugin = registry.Load("social_force", PluginKind::kPolicy);
  std::mt19937 rng(11);
  int steps_checked = 0, touching = 0;
  for (int scene = 0; scene < 60; ++scene) {
    Params params = Params::Defaults(plugin.schema);
    params.Set("guidance", scene % 3 == 0);
    if (scene % 3 == 2) params.Set("u0", 0.0);
    const testing::WalkScene drawn = testing::RandomWalkScene(rng);
    const StaticMap& map = drawn.map;
    const AgentState& self = drawn.self;
    testing::Walk(plugin, registry, params, &map, self, 120,
                  [&](int step, const Vec2& v, const AgentState& s) {
                    ASSERT_LE(v.norm(), 1.3 + 1e-9);
                    for (const Rect& rect : map.rectangles) {
                      const double gap = (s.position - NearestPoint(rect, s.position)).norm();
                      ASSERT_GE(gap, self.radius - 1e-9) << "scene " << scene << " step " << step;
                      touching += gap < self.radius + 0.02;
                    }
                    ++steps_checked;
                  });
  }
  EXPECT_EQ(steps_checked, 60 * 120);
  EXPECT_GT(touching, 100) << "the scenes must bring people against rectangles";
}

// Social force people in a suite: the same episodes on one thread and on two.
TEST(SocialForce, ASuiteOfSocialForcePeopleGivesTheSameEpisodesOnAnyThreads) {
  testing::TempDir dir;
  const auto file =
      dir.Write("sf.yaml",
                "name: sf\nepisodes: 6\nseed: 4\nworld: {source: random_rect, obstacles: 3}\n"
                "humans: {count: 5, policy: social_force}\nrobot: {sensors: [person]}\n"
                "rows:\n  - {label: orca, policy: orca}\n  - {label: sf, policy: social_force}\n");
  const auto runs = testing::RunOnOneAndTwoThreads(file, dir.path());
  ASSERT_EQ(runs[0].rows, 2u);
  EXPECT_EQ(runs[0].episodes, runs[1].episodes);
}

}  // namespace
}  // namespace crowdsim::social_force
