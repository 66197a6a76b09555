// ompl_planner costs: one global plan (default settings) in a 3-obstacle test room and in the
// hard Gibson floor plan, and one decision of the loaded plugin between plans (path
// following plus local avoidance of 5 people, ORCA or the action set).
#include <benchmark/benchmark.h>

#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/rng.h"
#include "global_planner.h"
#include "test_paths.h"

namespace crowdsim::ompl_planner {
namespace {

// Scenarios (robot start and goal, 5 humans) of a world, by episode index.
struct Worlds {
  PluginRegistry registry{{testing::PluginDir()}};
  std::shared_ptr<WorldSource> Make(const std::string& source, const std::string& level) {
    const LoadedPlugin& p = registry.Load(source, PluginKind::kWorld);
    Params params = Params::Defaults(p.schema);
    if (source == "random_rect") {
      params.Set("obstacles", std::int64_t{3});
    } else {
      params.Set("file", (testing::SourceDir() / "worlds/gibson" / (level + ".yaml")).string());
    }
    params.Set("split", std::string("test"));
    return registry.MakeWorld(p, params);
  }
};

Scenario Episode(const WorldSource& world, int k, int humans) {
  ScenarioRequest req;
  req.seed = DeriveSeed(7, world.Identity(), k);
  req.episode_index = k;
  req.num_humans = humans;
  return world.Make(req);
}

void PlanBench(benchmark::State& state, const std::string& source, const std::string& level,
               const std::string& planner_name) {
  Worlds worlds;
  const auto world = worlds.Make(source, level);
  std::vector<Scenario> scenarios;
  for (int k = 0; k < 20; ++k) scenarios.push_back(Episode(*world, k, 0));
  PlanSettings settings;
  settings.planner = planner_name;
  int k = 0, planned = 0;
  std::int64_t samples = 0;
  double length = 0.0;
  std::vector<std::unique_ptr<GlobalPlanner>> planners;
  std::vector<std::shared_ptr<const CollisionWorld>> maps;
  for (const Scenario& sc : scenarios) {
    maps.push_back(std::make_shared<CollisionWorld>(sc.map));
    planners.push_back(std::make_unique<GlobalPlanner>(maps.back(), settings));
  }
  for (auto _ : state) {
    const int i = k++ % static_cast<int>(scenarios.size());
    const PlanResult r = planners[i]->Plan(scenarios[i].robot_start, scenarios[i].robot_goal, 0.3,
                                           static_cast<std::uint64_t>(k));
    planned += r.attempts > 0;
    samples += r.samples;
    length += r.length;
    benchmark::DoNotOptimize(r.path.data());
  }
  state.counters["planner_runs_share"] = static_cast<double>(planned) / k;
  state.counters["samples"] = static_cast<double>(samples) / k;
  state.counters["path_m"] = length / k;
}

void BM_PlanThreeObstacleRoom(benchmark::State& state) {
  PlanBench(state, "random_rect", "", "rrtstar");
}
BENCHMARK(BM_PlanThreeObstacleRoom)->Unit(benchmark::kMillisecond);

void BM_PlanThreeObstacleRoomRrtConnect(benchmark::State& state) {
  PlanBench(state, "random_rect", "", "rrtconnect");
}
BENCHMARK(BM_PlanThreeObstacleRoomRrtConnect)->Unit(benchmark::kMillisecond);

void BM_PlanGibsonHard(benchmark::State& state) {
  PlanBench(state, "floorplan", "hard", "rrtstar");
}
BENCHMARK(BM_PlanGibsonHard)->Unit(benchmark::kMillisecond);

// One decision after the first (the path exists, no replanning): the observation is built by
// hand, 5 people walking.
void DecideBench(benchmark::State& state, const std::string& local) {
  Worlds worlds;
  const auto world = worlds.Make("random_rect", "");
  const Scenario sc = Episode(*world, 5, 5);
  const LoadedPlugin& p = worlds.registry.Load("ompl_planner", PluginKind::kPolicy);
  Params params = Params::Defaults(p.schema);
  params.Set("local", local);
  // The robot is not moved here: without this the stall rule would replan every 8 calls.
  params.Set("replan_stall_steps", std::int64_t{1000});
  const auto policy = worlds.registry.MakePolicy(p, params);
  EpisodeContext ctx;
  ctx.map = sc.map.get();
  ctx.seed = 1;
  policy->Reset(ctx);
  Observation obs;
  obs.self.position = sc.robot_start;
  obs.self.goal = sc.robot_goal;
  obs.self.heading = HeadingToGoal(obs.self);
  obs.frame = Frame::Make(obs.self.position, obs.self.heading);
  SensorReading reading;
  reading.sensor = "person";
  for (const HumanSpec& h : sc.humans) {
    reading.people.push_back(
        {obs.frame.PointToLocal(h.start), obs.frame.VectorToLocal(Vec2(0.3, -0.2)), h.radius});
  }
  obs.readings.push_back(reading);
  policy->Decide(obs);  // plans
  for (auto _ : state) benchmark::DoNotOptimize(policy->Decide(obs).velocity.x());
}

void BM_DecideOrca5People(benchmark::State& state) { DecideBench(state, "orca"); }
BENCHMARK(BM_DecideOrca5People)->Unit(benchmark::kMicrosecond);

void BM_DecideActions5People(benchmark::State& state) { DecideBench(state, "actions"); }
BENCHMARK(BM_DecideActions5People)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim::ompl_planner
