// One full episode step: the robot with both sensors (lidar2d 45 beams, person) and the linear
// policy, 5 ORCA humans, a 10 x 10 m room with 3 obstacles. Target: >= 50,000 steps/s. The
// unicycle robot (tracked, optionally acceleration-limited) should cost within 10% of it.
#include <benchmark/benchmark.h>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "scripted.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

struct Setup {
  PluginRegistry registry{{testing::PluginDir()}};
  std::shared_ptr<Policy> robot;
  std::vector<std::shared_ptr<Policy>> humans;
  std::shared_ptr<Sensor> lidar, person;
  EpisodeAgents agents;
  Scenario scenario;

  explicit Setup(const std::string& human_policy) {
    auto make_policy = [&](const std::string& name) {
      const auto& p = registry.Load(name, PluginKind::kPolicy);
      return registry.MakePolicy(p, Params::Defaults(p.schema));
    };
    auto make_sensor = [&](const std::string& name) {
      const auto& p = registry.Load(name, PluginKind::kSensor);
      return registry.MakeSensor(p, Params::Defaults(p.schema));
    };
    robot = make_policy("linear");
    lidar = make_sensor("lidar2d");
    person = make_sensor("person");
    agents.robot = robot.get();
    agents.sensors = {{"person", person.get()}, {"lidar2d", lidar.get()}};
    for (int i = 0; i < 5; ++i) {
      humans.push_back(make_policy(human_policy));
      agents.humans.push_back(humans.back().get());
    }
    // Three obstacles and humans crossing the room in both directions.
    scenario = testing::MakeScenario(testing::MakeRoom({Rect::FromCorners(-3.5, 1.0, -0.5, 4.0),
                                                        Rect::FromCorners(1.0, -4.0, 4.0, -1.0),
                                                        Rect::FromCorners(1.5, 1.5, 3.5, 3.5)}),
                                     Vec2(-4.0, -4.0), Vec2(4.2, 4.2),
                                     {{Vec2(-4, 0), Vec2(4, 0)},
                                      {Vec2(4, 0.5), Vec2(-4, 0.3)},
                                      {Vec2(0, -4.2), Vec2(0, 4.2)},
                                      {Vec2(-1, 4.5), Vec2(0.5, -4.5)},
                                      {Vec2(4.5, -0.2), Vec2(-4.5, -0.5)}});
  }
};

void BM_EpisodeStep(benchmark::State& state, const std::string& human_policy,
                    RobotKinematics kinematics = {}) {
  Setup s(human_policy);
  s.agents.kinematics = kinematics;
  SimConfig sim;
  sim.time_limit = 1e9;  // never time out inside the measurement
  auto episode = std::make_unique<Episode>(s.scenario, sim, s.agents);
  std::int64_t steps = 0;
  for (auto _ : state) {
    if (episode->done() || episode->time() > 20.0) {
      state.PauseTiming();
      episode = std::make_unique<Episode>(s.scenario, sim, s.agents);
      state.ResumeTiming();
    }
    episode->Step();
    ++steps;
  }
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(BM_EpisodeStep, orca_humans, std::string("orca"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeStep, linear_humans, std::string("linear"))
    ->Unit(benchmark::kMicrosecond);

RobotKinematics Unicycle(double accel_max, double angular_accel_max) {
  RobotKinematics k;
  k.model = KinematicsModel::kUnicycle;
  k.accel_max = accel_max;
  k.angular_accel_max = angular_accel_max;
  return k;
}
BENCHMARK_CAPTURE(BM_EpisodeStep, orca_humans_unicycle, std::string("orca"),
                  Unicycle(kInfinity, kInfinity))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeStep, orca_humans_unicycle_limited, std::string("orca"),
                  Unicycle(1.0, 2.0))
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim
