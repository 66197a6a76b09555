// ORCA humans left alone in the paper's 3-obstacle test layouts: they reach their goals
// (>= 95% within 60 s) and never overlap an obstacle. Runs the real plugins through the
// episode loop; the robot stands far outside the room (invisible, never in the way).
#include <gtest/gtest.h>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/rng.h"
#include "scripted.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

TEST(OrcaCrowd, HumansReachGoalsInThreeObstacleTestLayoutsAndStayOutOfObstacles) {
  PluginRegistry registry({testing::PluginDir()});
  const auto& world_plugin = registry.Load("random_rect", PluginKind::kWorld);
  Params wp = Params::Defaults(world_plugin.schema);
  wp.Set("obstacles", std::int64_t{3});
  wp.Set("split", std::string("test"));
  auto world = registry.MakeWorld(world_plugin, wp);
  const auto& orca = registry.Load("orca", PluginKind::kPolicy);
  std::vector<std::shared_ptr<Policy>> humans;
  EpisodeAgents agents;
  testing::ConstantVelocityPolicy robot(Vec2::Zero());
  agents.robot = &robot;
  for (int i = 0; i < 5; ++i) {
    humans.push_back(registry.MakePolicy(orca, Params::Defaults(orca.schema)));
    agents.humans.push_back(humans.back().get());
  }
  SimConfig sim;
  sim.time_limit = 60.0;
  int arrived = 0, total = 0, overlaps = 0;
  std::string first_overlap;
  for (int k = 0; k < 100; ++k) {
    ScenarioRequest req;
    req.seed = DeriveSeed(7, world->Identity(), k);
    req.episode_index = k;
    req.num_humans = 5;
    req.sim = sim;
    Scenario sc = world->Make(req);
    // The robot out of everybody's way: far off the room, on a map whose bounds reach it (a
    // start outside the map is refused).
    auto map = std::make_shared<StaticMap>(*sc.map);
    map->bounds = Rect::FromCorners(-300, -300, 300, 300);
    sc.map = map;
    sc.robot_start = Vec2(100, 100);
    sc.robot_goal = Vec2(200, 200);
    Episode ep(sc, sim, agents);
    while (!ep.done()) {
      ep.Step();
      for (const auto& h : ep.humans()) {
        if (ep.world().DiscOverlaps(h.position, h.radius - 1e-6)) {
          if (overlaps++ == 0) {
            first_overlap = sc.layout + " at t=" + std::to_string(ep.time()) + " (" +
                            std::to_string(h.position.x()) + ", " + std::to_string(h.position.y()) +
                            ")";
          }
        }
      }
    }
    ASSERT_EQ(ep.result().status, EpisodeStatus::kTimeout) << ep.result().error;
    arrived += ep.result().humans_at_goal;
    total += static_cast<int>(sc.humans.size());
  }
  EXPECT_EQ(overlaps, 0) << "first overlap: " << first_overlap;
  const double share = static_cast<double>(arrived) / total;
  RecordProperty("humans_arrived_share", std::to_string(share));
  EXPECT_GE(share, 0.95) << arrived << " of " << total << " humans reached their goals";
}

}  // namespace
}  // namespace crowdsim
