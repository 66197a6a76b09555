// The person sensor's reading with 20 people in a real floor plan (Gibson hard), as loaded by the
// harness: all around and unlimited (CrowdNav's), and with a 180-degree field of view and
// occlusion by rectangles, and by rectangles and people (issue 48's target: <= 2 us a reading).
// BM_TrackedReading: the full realistic detector (180 degrees, occlusion by rectangles and people,
// 0.1 m noise, 0.9 detection, 0.5 phantoms a reading) with the nearest-neighbour tracker and
// estimated velocities, at step N of an episode: continued from the memo of the steps before
// (the episode's case: one new frame a step) or replaying all N steps (no memo).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <span>
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

void BM_TrackedReading(benchmark::State& state, bool memo) {
  const int steps = static_cast<int>(state.range(0));
  const WorldFile plan = ReadWorldFile(testing::SourceDir() / "worlds" / "gibson" / "hard.yaml");
  auto map = std::make_shared<StaticMap>();
  map->bounds = plan.bounds;
  map->rectangles = plan.rectangles;
  const CollisionWorld world(map);
  std::mt19937_64 rng(48);
  std::uniform_int_distribution<std::size_t> pick(0, plan.free_points.size() - 1);
  // 20 people walking circles of 0.5 m radius at 0.67 m/s round random free points (the scene
  // stays alike step after step, so the steps cost alike); the robot, heading 0.7 rad, at the
  // one of 64 random free points that sees the most of them at step 0 (a busy view).
  constexpr double kDt = 0.25, kCircle = 0.5, kTurn = 0.67 / kCircle * kDt;  // rad a step
  std::vector<Vec2> centres;
  for (int i = 0; i < 20; ++i) centres.push_back(plan.free_points[pick(rng)]);
  std::vector<SensedFrame> frames(static_cast<std::size_t>(steps) + 1);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (int i = 0; i < 20; ++i) {
      const double a = i + kTurn * static_cast<double>(k);
      AgentState h;
      h.position = centres[i] + kCircle * Vec2(std::cos(a), std::sin(a));
      h.velocity = 0.67 * Vec2(-std::sin(a), std::cos(a));
      h.radius = 0.3;
      frames[k].humans.push_back(h);
    }
  }
  PluginRegistry registry({testing::PluginDir()});
  const LoadedPlugin& plugin = registry.Load("person", PluginKind::kSensor);
  Params params = Params::Defaults(plugin.schema);
  params.Set("fov_deg", 180.0);
  params.Set("occlusion", std::string("obstacles+people"));
  params.Set("position_noise", 0.1);
  params.Set("detection_prob", 0.9);
  params.Set("false_detections", 0.5);
  params.Set("velocity", std::string("estimated"));
  params.Set("tracker", std::string("nearest"));
  const auto sensor = registry.MakeSensor(plugin, params);
  Vec2 eye = Vec2::Zero();
  std::size_t most = 0;
  for (int c = 0; c < 64; ++c) {
    const Vec2 at = plan.free_points[pick(rng)];
    AgentState robot;
    robot.position = at;
    const Frame frame = Frame::Make(at, 0.7);
    SensorReading r;
    sensor->Sense(SenseInput{robot, frame, frames[0].humans, world, 7, 0, kDt}, &r);
    if (r.people.size() > most) {
      most = r.people.size();
      eye = at;
    }
  }
  for (SensedFrame& f : frames) {
    f.robot.position = eye;
    f.robot.heading = 0.7;
    f.frame = Frame::Make(eye, 0.7);
  }
  const SensedFrame& now = frames.back();
  const std::span<const SensedFrame> past(frames.data(), static_cast<std::size_t>(steps));
  // A history id of its own per run (a memo is keyed on it): 0 replays every reading.
  const std::uint64_t id = memo ? static_cast<std::uint64_t>(steps) : 0;
  const SenseInput in{now.robot, now.frame, now.humans, world, 7, steps, kDt, past, id};
  SensorReading reading;
  std::size_t seen = 0;
  for (auto _ : state) {
    sensor->Sense(in, &reading);
    seen += reading.people.size();
    benchmark::DoNotOptimize(reading);
  }
  state.counters["people_seen"] =
      benchmark::Counter(static_cast<double>(seen) / static_cast<double>(state.iterations()));
}
BENCHMARK_CAPTURE(BM_TrackedReading, memo, true)->Arg(1)->Arg(10)->Arg(50)->Arg(100);
BENCHMARK_CAPTURE(BM_TrackedReading, replay_all, false)->Arg(1)->Arg(10)->Arg(50)->Arg(100);

}  // namespace
}  // namespace crowdsim
