// The built `ompl_planner` plugin driven through the episode loop: with nobody around it
// reaches every goal of the 3-obstacle test layouts and of the three Gibson floor plans
// without ever touching a rectangle, and every episode replays bit for bit, in one thread or
// in two at once.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/rng.h"
#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

struct Outcome {
  EpisodeStatus status = EpisodeStatus::kRunning;
  int steps_inside_obstacle = 0;
  std::string error;
  std::vector<Vec2> robot_positions;
};

class OmplPlannerEpisodes : public ::testing::Test {
 protected:
  std::shared_ptr<WorldSource> RandomRect(int obstacles) {
    const LoadedPlugin& p = registry_.Load("random_rect", PluginKind::kWorld);
    Params params = Params::Defaults(p.schema);
    params.Set("obstacles", std::int64_t{obstacles});
    params.Set("split", std::string("test"));
    return registry_.MakeWorld(p, params);
  }
  std::shared_ptr<WorldSource> Gibson(const std::string& level) {
    const LoadedPlugin& p = registry_.Load("floorplan", PluginKind::kWorld);
    Params params = Params::Defaults(p.schema);
    params.Set("file", (testing::SourceDir() / "worlds/gibson" / (level + ".yaml")).string());
    params.Set("split", std::string("test"));
    return registry_.MakeWorld(p, params);
  }
  std::shared_ptr<Policy> Robot(const std::string& planner = "", const std::string& local = "") {
    const LoadedPlugin& p = registry_.Load("ompl_planner", PluginKind::kPolicy);
    Params params = Params::Defaults(p.schema);
    if (!planner.empty()) params.Set("planner", planner);
    if (!local.empty()) params.Set("local", local);
    return registry_.MakePolicy(p, params);
  }
  std::shared_ptr<Policy> Human() {
    const LoadedPlugin& p = registry_.Load("orca", PluginKind::kPolicy);
    return registry_.MakePolicy(p, Params::Defaults(p.schema));
  }
  std::shared_ptr<Sensor> PersonSensor() {
    const LoadedPlugin& p = registry_.Load("person", PluginKind::kSensor);
    return registry_.MakeSensor(p, Params::Defaults(p.schema));
  }

  Scenario Make(const WorldSource& world, int k, int humans, const SimConfig& sim) {
    ScenarioRequest req;
    req.seed = DeriveSeed(7, world.Identity(), k);
    req.episode_index = k;
    req.num_humans = humans;
    req.sim = sim;
    return world.Make(req);
  }

  // Runs one episode with fresh policies (as a suite worker would own them).
  Outcome Run(const Scenario& sc, const SimConfig& sim, const std::string& planner = "",
              const std::string& local = "") {
    std::shared_ptr<Policy> robot = Robot(planner, local);
    std::shared_ptr<Sensor> person = PersonSensor();
    std::vector<std::shared_ptr<Policy>> humans;
    EpisodeAgents agents;
    agents.robot = robot.get();
    agents.sensors = {{"person", person.get()}};
    for (std::size_t i = 0; i < sc.humans.size(); ++i) {
      humans.push_back(Human());
      agents.humans.push_back(humans.back().get());
    }
    Episode ep(sc, sim, agents);
    Outcome out;
    while (!ep.done()) {
      ep.Step();
      out.robot_positions.push_back(ep.robot().position);
      if (ep.world().DiscOverlaps(ep.robot().position, ep.robot().radius - 1e-6)) {
        ++out.steps_inside_obstacle;
      }
    }
    out.status = ep.result().status;
    out.error = ep.result().error;
    return out;
  }

  PluginRegistry registry_{{testing::PluginDir()}};
};

TEST_F(OmplPlannerEpisodes, ReachesEveryGoalOfTheThreeObstacleTestLayoutsWithoutHumans) {
  const auto world = RandomRect(3);
  const SimConfig sim;
  int successes = 0;
  std::string failures;
  for (int k = 0; k < 100; ++k) {
    const Scenario sc = Make(*world, k, 0, sim);
    const Outcome out = Run(sc, sim);
    EXPECT_EQ(out.steps_inside_obstacle, 0) << sc.layout;
    if (out.status == EpisodeStatus::kSuccess) {
      ++successes;
    } else {
      failures += " " + sc.layout + ":" + EpisodeStatusName(out.status) + out.error;
    }
  }
  EXPECT_EQ(successes, 100) << "failed:" << failures;
}

class OmplPlannerGibson : public OmplPlannerEpisodes,
                          public ::testing::WithParamInterface<const char*> {};

TEST_P(OmplPlannerGibson, ReachesEveryGoalOfASampleOfTheTestPairsWithoutHumans) {
  const auto world = Gibson(GetParam());
  const SimConfig sim;  // the paper's 25 s limit
  int successes = 0, total = 0;
  std::string failures;
  // Every 5th of the 500 test pairs keeps CI fast; all 500 pass as well (about 57 s for the
  // three plans on the 2-core development machine).
  for (int k = 0; k < 500; k += 5) {
    const Scenario sc = Make(*world, k, 0, sim);
    const Outcome out = Run(sc, sim);
    EXPECT_EQ(out.steps_inside_obstacle, 0) << "pair " << k;
    ++total;
    if (out.status == EpisodeStatus::kSuccess) {
      ++successes;
    } else {
      failures += " pair " + std::to_string(k) + ":" + EpisodeStatusName(out.status) + out.error;
    }
  }
  EXPECT_EQ(successes, total) << "failed:" << failures;
}

INSTANTIATE_TEST_SUITE_P(Plans, OmplPlannerGibson, ::testing::Values("easy", "medium", "hard"));

// Same episode (5 ORCA humans), fresh policies each time: twice in this thread, then twice
// at once in two threads. Every robot position must match bit for bit.
TEST_F(OmplPlannerEpisodes, EpisodesReplayIdenticallyInOneThreadAndInTwo) {
  const auto world = RandomRect(3);
  const SimConfig sim;
  const std::vector<std::pair<std::string, std::string>> configs = {
      {"rrtstar", "orca"},    {"rrtstar", "actions"}, {"informed_rrtstar", "orca"},
      {"rrtconnect", "orca"}, {"rrt", "actions"},     {"lazyprmstar", "orca"}};
  for (const auto& [planner, local] : configs) {
    for (int k : {3, 17, 42}) {
      const Scenario sc = Make(*world, k, 5, sim);
      const Outcome first = Run(sc, sim, planner, local);
      const Outcome second = Run(sc, sim, planner, local);
      const std::string what = planner + "/" + local + " " + sc.layout;
      EXPECT_EQ(first.status, second.status) << what;
      EXPECT_EQ(first.robot_positions, second.robot_positions) << what;
      Outcome a, b;
      std::thread ta([&] { a = Run(sc, sim, planner, local); });
      std::thread tb([&] { b = Run(sc, sim, planner, local); });
      ta.join();
      tb.join();
      EXPECT_EQ(a.robot_positions, first.robot_positions) << what << " (thread a)";
      EXPECT_EQ(b.robot_positions, first.robot_positions) << what << " (thread b)";
    }
  }
}

// The command line with the plugin unloaded before exit: a run and a validate of a row whose
// local mode never calls ORCA exited with SIGSEGV (139) after writing every file, when OMPL's
// static registry dropped a control block whose code had been unloaded with the plugin.
TEST(OmplPlannerCommandLine, ExitsCleanlyAfterRunAndValidateWithLocalActions) {
  testing::TempDir dir;
  const auto suite = dir.Write("actions.yaml", R"(name: ompl_actions
episodes: 2
world: {source: random_rect, obstacles: 3}
humans: {count: 5, policy: orca}
robot:
  sensors: [person]
rows:
  - {label: p, policy: ompl_planner, params: {local: actions}}
)");
  const std::string exe = (testing::BinaryDir() / "bin" / "crowdsim-bench").string();
  const auto [rc, text] = testing::Shell(exe + " run " + suite.string() + " --quiet --out " +
                                         (dir.path() / "out").string());
  EXPECT_EQ(rc, 0) << text;
  const auto [vrc, vtext] = testing::Shell(exe + " validate " + suite.string());
  EXPECT_EQ(vrc, 0) << vtext;
}

}  // namespace
}  // namespace crowdsim
