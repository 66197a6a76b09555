// The person sensor's reading with 20 people in a real floor plan (Gibson hard), as loaded by the
// harness: all around and unlimited (CrowdNav's), and with a 180-degree field of view and
// occlusion by rectangles, and by rectangles and people (issue 48's target: <= 2 us a reading).
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/collision_world.h"
#include "crowdsim/world_file.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

void BM_PersonReading20PeopleFloorPlan(benchmark::State& state, double fov_deg,
                                       const char* occlusion) {
  const WorldFile plan = ReadWorldFile(testing::SourceDir() / "worlds" / "gibson" / "hard.yaml");
  auto map = std::make_shared<StaticMap>();
  map->bounds = plan.bounds;
  map->rectangles = plan.rectangles;
  const CollisionWorld world(map);
  // 20 people and 64 robot places at random free points of the plan (seeded).
  std::mt19937_64 rng(48);
  std::uniform_int_distribution<std::size_t> pick(0, plan.free_points.size() - 1);
  std::vector<AgentState> humans;
  for (int i = 0; i < 20; ++i) {
    AgentState h;
    h.position = plan.free_points[pick(rng)];
    h.velocity = Vec2(0.6, -0.3);
    h.radius = 0.3;
    humans.push_back(h);
  }
  std::vector<Vec2> robots;
  for (int i = 0; i < 64; ++i) robots.push_back(plan.free_points[pick(rng)]);
  PluginRegistry registry({testing::PluginDir()});
  const LoadedPlugin& plugin = registry.Load("person", PluginKind::kSensor);
  Params params = Params::Defaults(plugin.schema);
  params.Set("fov_deg", fov_deg);
  params.Set("occlusion", std::string(occlusion));
  const auto sensor = registry.MakeSensor(plugin, params);
  SensorReading reading;
  std::size_t k = 0, seen = 0;
  for (auto _ : state) {
    AgentState robot;
    robot.position = robots[k++ % robots.size()];
    const Frame frame = Frame::Make(robot.position, 0.7);
    sensor->Sense(SenseInput{robot, frame, humans, world}, &reading);
    seen += reading.people.size();
    benchmark::DoNotOptimize(reading);
  }
  state.counters["people_seen"] =
      benchmark::Counter(static_cast<double>(seen) / static_cast<double>(state.iterations()));
}
BENCHMARK_CAPTURE(BM_PersonReading20PeopleFloorPlan, all_around, 360.0, "none");
BENCHMARK_CAPTURE(BM_PersonReading20PeopleFloorPlan, fov180_obstacles, 180.0, "obstacles");
BENCHMARK_CAPTURE(BM_PersonReading20PeopleFloorPlan, fov360_obstacles_people, 360.0,
                  "obstacles+people");
BENCHMARK_CAPTURE(BM_PersonReading20PeopleFloorPlan, fov180_obstacles_people, 180.0,
                  "obstacles+people");

}  // namespace
}  // namespace crowdsim
