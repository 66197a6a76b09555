// What the whole-step benchmarks share: the robot and humans a suite row would make (each
// plugin with its schema's defaults), and a timed loop of Episode::Step that reports the cost
// per agent-step. Header-only, so every tests/bench/*_bench.cc stays one executable.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "scripted.h"
#include "test_paths.h"

namespace crowdsim::bench {

/// The robot of a benchmark row.
enum class RobotKind {
  kOrcaLidarPerson,  ///< ORCA policy, lidar2d (45 beams) + person sensors: the costly robot
  kStill,            ///< stands still and senses nothing: the step is the humans' alone
};

/// The plugins of one row, owned here; `agents` borrows them as RowInstance does.
struct RowAgents {
  PluginRegistry registry{{testing::PluginDir()}};
  std::vector<std::shared_ptr<Policy>> policies;
  std::vector<std::shared_ptr<Sensor>> sensors;
  EpisodeAgents agents;

  RowAgents(RobotKind robot, int humans, const std::string& human_policy = "orca") {
    if (robot == RobotKind::kOrcaLidarPerson) {
      agents.robot = Keep(MakePolicy("orca"));
      // The order of a suite's `sensors: [lidar2d, person]`.
      for (const char* name : {"lidar2d", "person"}) {
        const LoadedPlugin& p = registry.Load(name, PluginKind::kSensor);
        sensors.push_back(registry.MakeSensor(p, Params::Defaults(p.schema)));
        agents.sensors.push_back({name, sensors.back().get()});
      }
    } else {
      agents.robot = Keep(std::make_shared<testing::ConstantVelocityPolicy>(Vec2::Zero()));
    }
    for (int i = 0; i < humans; ++i) agents.humans.push_back(Keep(MakePolicy(human_policy)));
  }

  std::shared_ptr<WorldSource> MakeWorld(
      const std::string& name, const std::vector<std::pair<std::string, ParamValue>>& set = {}) {
    const LoadedPlugin& p = registry.Load(name, PluginKind::kWorld);
    Params params = Params::Defaults(p.schema);
    for (const auto& [key, value] : set) params.Set(key, value);
    return registry.MakeWorld(p, params);
  }

 private:
  std::shared_ptr<Policy> MakePolicy(const std::string& name) {
    const LoadedPlugin& p = registry.Load(name, PluginKind::kPolicy);
    return registry.MakePolicy(p, Params::Defaults(p.schema));
  }
  Policy* Keep(std::shared_ptr<Policy> policy) {
    policies.push_back(std::move(policy));
    return policies.back().get();
  }
};

/// Episode k's scenario of `world` as a suite asks for it: seed `first_seed` + k, episode index
/// k, `humans` humans (for TimeSteps).
inline auto SuiteScenarios(const WorldSource& world, std::uint64_t first_seed, int humans) {
  return [&world, first_seed, humans](int episode) {
    ScenarioRequest request;
    request.seed = first_seed + static_cast<std::uint64_t>(episode);
    request.episode_index = episode;
    request.num_humans = humans;
    return world.Make(request);
  };
}

/// Times Episode::Step on the episodes `make_scenario(k)` gives for k = 0, 1, ..., restarting
/// (untimed) with the next one when an episode ends or reaches `restart_after` seconds, so that
/// every measured step is one of an episode's first steps, while the crowd is still crossing;
/// the robot is visible to the humans. Counters: per_agent_step (CPU time of a step over
/// `agents_per_step`, the agents that decide each step), steps_per_s, present (the mean number
/// of humans present at a step: all of them, unless a recorded crowd's people appear and leave)
/// and per_present_step (CPU time of a step over the humans present).
///
/// Give every episode its own scenario, as a suite does: an episode replayed over and over is
/// learned by the processor's branch predictor when it is short. On the 2-core AMD EPYC (Zen 4)
/// VM, 20 ORCA humans replaying one 80-step episode cost 273 ns per agent-step, 414 ns with a
/// new scenario per episode; 1,000 humans cost the same either way (546 ns).
template <typename MakeScenario>
void TimeSteps(benchmark::State& state, MakeScenario make_scenario, const EpisodeAgents& agents,
               int agents_per_step, double restart_after = 20.0) {
  SimConfig sim;
  sim.time_limit = 1e9;  // the restart rule, not a timeout, ends the measured episodes
  // Humans who see the robot avoid it: with the paper's invisible robot, an episode in a
  // dense crowd ends in a collision within a few steps, and only its first steps, with
  // everybody still accelerating from rest, would be measured.
  sim.robot_visible = true;
  Scenario scenario = make_scenario(0);
  auto episode = std::make_unique<Episode>(scenario, sim, agents);
  int episodes = 1;
  double present = 0.0;  // humans present, summed over the measured steps
  for (auto _ : state) {
    if (episode->done() || episode->time() >= restart_after) {
      state.PauseTiming();
      scenario = make_scenario(episodes);
      episode = std::make_unique<Episode>(scenario, sim, agents);
      ++episodes;
      state.ResumeTiming();
    }
    present += static_cast<double>(episode->present_humans().size());
    episode->Step();
  }
  // Steps per measured episode: at most restart_after / time_step, fewer when episodes end.
  state.counters["episode_steps"] =
      static_cast<double>(state.iterations()) / static_cast<double>(episodes);
  state.counters["episodes"] = episodes;
  // An inverted iteration-invariant rate is CPU time / (iterations x value), shown as a time.
  state.counters["per_agent_step"] = benchmark::Counter(
      agents_per_step, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["steps_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
  const double per_step = present / static_cast<double>(std::max<int64_t>(state.iterations(), 1));
  state.counters["present"] = per_step;
  state.counters["per_present_step"] = benchmark::Counter(
      per_step, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace crowdsim::bench
