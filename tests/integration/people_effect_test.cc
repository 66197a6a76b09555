// The robot's effect on the people: each person's walk against the same episode replayed without
// the robot, on a hand-built episode with hand-computed values, zero for a robot nobody sees, and
// as a suite's metric family.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/play_episode.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "scripted.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::ConstantVelocityPolicy;
using testing::MakeMap;
using testing::MakeScenario;

// Walks to its goal at v_pref, and stands while anybody is within 1.5 m (or it is at the goal).
class WalkUntilBlocked final : public Policy {
 public:
  Action Decide(const Observation& obs) override {
    const auto all = obs.agents->agents();
    for (size_t k = 0; k < all.size(); ++k) {
      if (static_cast<int>(k) != obs.self_index &&
          (all[k].position - obs.self.position).norm() < 1.5)
        return Action{};
    }
    const Vec2 d = obs.self.goal - obs.self.position;
    if (d.norm() < 0.05) return Action{};
    return Action{d / d.norm() * obs.self.v_pref};
  }
};

SocialMetrics Effect(bool robot_visible, const Vec2& robot_at) {
  // A person walks from (0, 0) to (10, 0) at 1 m/s; the robot stands at `robot_at` until the 25 s
  // timeout (100 steps), its goal out of reach.
  const Scenario sc =
      MakeScenario(MakeMap({}), robot_at, robot_at + Vec2(0, 15), {{Vec2(0, 0), Vec2(10, 0)}});
  ConstantVelocityPolicy robot(Vec2::Zero());
  WalkUntilBlocked person;
  SimConfig sim;
  sim.robot_visible = robot_visible;
  Episode ep(sc, sim, EpisodeAgents{&robot, {&person}, {}, {}});
  const EpisodeOutcome out = PlayEpisode(ep, kEffectMetrics);
  EXPECT_EQ(out.status, EpisodeStatus::kTimeout);
  EXPECT_EQ(out.steps, 100);
  return out.social;
}

// Seeing the robot at (4, 0), the person stops at x = 2.75 (1.25 m from it) and stands: 7.25 m
// short of its goal, 2.75 m walked. Without the robot it walks the 10 m to its goal. Both
// accelerate once (0 -> 1 m/s in a step: 4 m/s^2) and stop once: the same mean, 8 / 100 m/s^2.
TEST(PeopleEffect, APersonStoppedByTheRobotLosesTheWayItDidNotWalk) {
  const SocialMetrics m = Effect(true, Vec2(4, 0));
  EXPECT_NEAR(m.people_lost_progress, 7.25, 1e-9);
  EXPECT_NEAR(m.people_path_added, 2.75 - 10.0, 1e-9);
  EXPECT_NEAR(m.people_accel_added, 0.0, 1e-9);
}

TEST(PeopleEffect, ARobotNobodySeesHasNoEffect) {
  const SocialMetrics m = Effect(false, Vec2(4, 2));  // beside the person's line: no collision
  EXPECT_EQ(m.people_lost_progress, 0.0);
  EXPECT_EQ(m.people_path_added, 0.0);
  EXPECT_EQ(m.people_accel_added, 0.0);
}

// A suite naming one of them gets the family's three columns alone; people who see the robot give
// way, so the effect is not zero on average; without people it does not apply.
TEST(PeopleEffect, ASuiteNamingOneGetsTheFamily) {
  testing::TempDir dir;
  PluginRegistry registry{{testing::PluginDir()}};
  auto load = [&](const std::string& humans) {
    const std::string yaml =
        "name: effect\nepisodes: 10\nseed: 5\nsim: {robot_visible: true}\n"
        "world: {source: random_rect, obstacles: 1, split: test}\nhumans: {" +
        humans + "}\nrobot:\n  sensors: [person]\ncolumns: [people_lost_progress]\nrows:\n" +
        "  - {label: linear, policy: linear}\n";
    SuiteLoadResult r = LoadSuite(dir.Write("suite.yaml", yaml), registry);
    EXPECT_TRUE(r.suite);
    return *r.suite;
  };
  auto run = [&](const Suite& s, const std::string& out) {
    RunOptions o;
    o.out_dir = dir.path() / out;
    o.jobs = 2;
    o.progress = false;
    RunSuite(s, registry, o);
    return ReadEpisodesCsv(o.out_dir / "episodes.csv");
  };
  const Suite with = load("count: 5, policy: orca");
  EXPECT_EQ(with.social_metrics, kEffectMetrics);
  EXPECT_NE(with.canonical.find("effect_metrics"), std::string::npos);
  double sum = 0.0;
  for (const EpisodeLine& e : run(with, "with")) {
    ASSERT_TRUE(std::isfinite(e.outcome.social.people_lost_progress));
    sum += std::abs(e.outcome.social.people_path_added);
  }
  EXPECT_GT(sum, 0.0);
  const std::string header = testing::ReadText(dir.path() / "with" / "episodes.csv");
  EXPECT_EQ(header.substr(0, header.find('\n')), EpisodeCsvHeader(kEffectMetrics));
  for (const EpisodeLine& e : run(load("count: 0"), "empty"))
    EXPECT_TRUE(std::isnan(e.outcome.social.people_lost_progress));
}

}  // namespace
}  // namespace crowdsim
