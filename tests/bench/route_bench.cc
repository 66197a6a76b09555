// The route sensor on the hard floor plan (worlds/gibson/hard.yaml): a reading with its field
// cached (what a value policy pays per lookahead candidate) and a reading that builds the field
// (once per episode: a new goal); the path-efficiency metric's shortest path (a field each).
#include <benchmark/benchmark.h>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/social_metrics.h"
#include "crowdsim/collision_world.h"
#include "crowdsim/world_file.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

struct HardPlan {
  HardPlan()
      : file(ReadWorldFile(testing::SourceDir() / "worlds" / "gibson" / "hard.yaml")),
        world(std::make_shared<const StaticMap>(file.ToStaticMap())),
        registry({testing::PluginDir()}) {
    const LoadedPlugin& p = registry.Load("route", PluginKind::kSensor);
    sensor = registry.MakeSensor(p, Params::Defaults(p.schema));
  }

  // One reading of a robot at `from` heading for `goal`.
  void Sense(const Vec2& from, const Vec2& goal, SensorReading* out) const {
    AgentState robot;
    robot.position = from;
    robot.goal = goal;
    robot.heading = HeadingToGoal(robot);
    const Frame frame = Frame::Make(from, robot.heading);
    sensor->Sense(SenseInput{robot, frame, {}, world}, out);
  }

  WorldFile file;
  CollisionWorld world;
  PluginRegistry registry;
  std::shared_ptr<Sensor> sensor;
};

const HardPlan& Plan() {
  static const HardPlan plan;
  return plan;
}

// The test trips' starts against one goal: the field is built once, then every reading is the
// path pull and the waypoint.
void BM_RouteReading_Hard(benchmark::State& state) {
  const HardPlan& plan = Plan();
  const auto& trips = plan.file.test_pairs;
  const Vec2 goal = trips.front().goal;
  SensorReading reading;
  size_t k = 0;
  for (auto _ : state) {
    plan.Sense(trips[k].start, goal, &reading);
    benchmark::DoNotOptimize(reading.values.data());
    k = (k + 1) % trips.size();
  }
}
BENCHMARK(BM_RouteReading_Hard);

// A new goal every reading (more goals than the cache keeps): the field is built each time.
void BM_RouteFieldBuild_Hard(benchmark::State& state) {
  const HardPlan& plan = Plan();
  const auto& trips = plan.file.test_pairs;
  SensorReading reading;
  size_t k = 0;
  for (auto _ : state) {
    plan.Sense(trips[k].start, trips[(k + 17) % trips.size()].goal, &reading);
    benchmark::DoNotOptimize(reading.values.data());
    k = (k + 1) % trips.size();
  }
}
BENCHMARK(BM_RouteFieldBuild_Hard)->Unit(benchmark::kMillisecond);

// The path-efficiency metric's shortest free path of a test trip: a field per episode.
void BM_ShortestFreePath_Hard(benchmark::State& state) {
  const HardPlan& plan = Plan();
  const auto& trips = plan.file.test_pairs;
  size_t k = 0;
  for (auto _ : state) {
    AgentState robot;
    robot.position = trips[k].start;
    robot.goal = trips[k].goal;
    benchmark::DoNotOptimize(ShortestFreePath(plan.world.map(), robot));
    k = (k + 1) % trips.size();
  }
}
BENCHMARK(BM_ShortestFreePath_Hard)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace crowdsim
