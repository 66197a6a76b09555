// Costs of the learned policies: batched value evaluation of the 16 lookahead candidates,
// one SGD step on a batch of 100, and whole episodes (lookahead included) in the paper's
// test conditions (1-obstacle room, 5 ORCA humans, 45-beam lidar).
#include <benchmark/benchmark.h>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/rng.h"
#include "value_rl/state_encoding.h"
#include "value_rl/value_policy.h"

namespace crowdsim::value_rl {
namespace {

ValueRlConfig Config(Model model, SensorSet sensors) {
  ValueRlConfig c;
  c.model = model;
  c.sensors = sensors;
  c.lidar_beams = 45;
  return c;
}

/// Plausible random states: 5 humans, 45 beams.
std::vector<EncodedState> RandomStates(const ValueRlConfig& c, int n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<EncodedState> states(n);
  for (auto& s : states) {
    s.values = {static_cast<float>(rng.Uniform(0, 10)),
                1.0f,
                0.0f,
                0.3f,
                static_cast<float>(rng.Uniform(-1, 1)),
                static_cast<float>(rng.Uniform(-1, 1))};
    for (int b = 0; b < c.LidarInputs(); ++b) s.values.push_back(static_cast<float>(rng.Uniform()));
    if (UsesPerson(c.sensors)) {
      for (int h = 0; h < 5; ++h) {
        const float x = static_cast<float>(rng.Uniform(-5, 5)),
                    y = static_cast<float>(rng.Uniform(-5, 5));
        s.values.insert(s.values.end(), {x, y, static_cast<float>(rng.Uniform(-1, 1)),
                                         static_cast<float>(rng.Uniform(-1, 1)), 0.3f,
                                         std::sqrt(x * x + y * y), 0.6f});
      }
    }
  }
  return states;
}

std::vector<const EncodedState*> Pointers(const std::vector<EncodedState>& states) {
  std::vector<const EncodedState*> p;
  for (const auto& s : states) p.push_back(&s);
  return p;
}

void Args(benchmark::internal::Benchmark* b) {
  b->ArgNames({"sarl", "sensors"});  // sensors: 0 person, 1 lidar, 2 lidar+person
  for (int model : {0, 1}) {
    for (int sensors : {0, 1, 2}) b->Args({model, sensors});
  }
}

ValueRlConfig FromArgs(const benchmark::State& state) {
  return Config(state.range(0) ? Model::kSarl : Model::kCadrl,
                static_cast<SensorSet>(state.range(1)));
}

void BM_Value16Candidates(benchmark::State& state) {
  ValuePolicy policy(FromArgs(state));
  const auto states = RandomStates(policy.config(), 16, 1);
  const auto ptrs = Pointers(states);
  for (auto _ : state) benchmark::DoNotOptimize(policy.Values(ptrs));
}
BENCHMARK(BM_Value16Candidates)->Apply(Args)->Unit(benchmark::kMicrosecond);

void BM_SgdStepBatch100(benchmark::State& state) {
  ValuePolicy policy(FromArgs(state));
  policy.SetLearningRate(0.001, 0.9);
  const auto states = RandomStates(policy.config(), 100, 2);
  const auto ptrs = Pointers(states);
  std::vector<float> targets(100);
  for (size_t i = 0; i < targets.size(); ++i) targets[i] = 0.01f * static_cast<float>(i % 50);
  for (auto _ : state) benchmark::DoNotOptimize(policy.TrainBatch(ptrs, targets));
}
BENCHMARK(BM_SgdStepBatch100)->Apply(Args)->Unit(benchmark::kMicrosecond);

/// The plugin objects of the paper's test conditions.
struct World {
  PluginRegistry registry;
  std::shared_ptr<WorldSource> world;
  std::vector<std::shared_ptr<Sensor>> sensors;
  std::vector<std::shared_ptr<Policy>> humans;
  EpisodeAgents agents;
  SimConfig sim;

  World() {
    const LoadedPlugin& rect = registry.Load("random_rect", PluginKind::kWorld);
    Params wp = Params::Defaults(rect.schema);
    wp.Set("split", std::string("train"));
    world = registry.MakeWorld(rect, wp);
    for (const char* name : {"lidar2d", "person"}) {
      const LoadedPlugin& p = registry.Load(name, PluginKind::kSensor);
      sensors.push_back(registry.MakeSensor(p, Params::Defaults(p.schema)));
      agents.sensors.push_back({name, sensors.back().get()});
    }
    const LoadedPlugin& orca = registry.Load("orca", PluginKind::kPolicy);
    for (int i = 0; i < 5; ++i) {
      humans.push_back(registry.MakePolicy(orca, Params::Defaults(orca.schema)));
      agents.humans.push_back(humans.back().get());
    }
  }

  Scenario Make(int k) const {
    ScenarioRequest req;
    req.seed = DeriveSeed(1, world->Identity(), k);
    req.episode_index = k;
    req.num_humans = 5;
    return world->Make(req);
  }
};

/// A greedy episode of a trained-like (IL) policy is what suites run; an untrained network
/// wanders to the time limit, so the steps per second are the figure to read.
void BM_GreedyEpisode(benchmark::State& state) {
  World w;
  ValuePolicy policy(FromArgs(state));
  w.agents.robot = &policy;
  int k = 0;
  int64_t steps = 0;
  for (auto _ : state) {
    const Scenario scenario = w.Make(k++);
    Episode episode(scenario, w.sim, w.agents);
    steps += episode.Run().steps;
  }
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  state.counters["steps/episode"] =
      static_cast<double>(steps) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_GreedyEpisode)->Apply(Args)->Unit(benchmark::kMillisecond);

/// One RL training episode as the trainer runs it: epsilon-greedy episode with lookahead,
/// state encoding, TD targets from the target network, 100 SGD steps on batches of 100.
/// The policy is made from `config`; the robot has `kinematics`.
void TimeTrainingEpisodes(benchmark::State& state, const ValueRlConfig& config,
                          const RobotKinematics& kinematics) {
  World w;
  w.agents.kinematics = kinematics;
  ValuePolicy policy(config);
  policy.SetLearningRate(0.001, 0.9);
  const auto memory = RandomStates(policy.config(), 2000, 3);
  std::vector<float> memory_values(memory.size(), 0.1f);
  w.agents.robot = &policy;
  Rng rng(4);
  int k = 0;
  std::int64_t steps = 0;
  for (auto _ : state) {
    policy.SetExploration(Exploration{0.7, static_cast<std::uint64_t>(k)});
    const Scenario scenario = w.Make(k++);
    Episode episode(scenario, w.sim, w.agents);
    std::vector<EncodedState> states;
    while (!episode.done()) {
      episode.Step();
      states.push_back(policy.Encode(episode.last_robot_observation()));
    }
    steps += static_cast<std::int64_t>(states.size());
    benchmark::DoNotOptimize(policy.TargetValues(Pointers(states)));
    for (int b = 0; b < 100; ++b) {
      std::vector<const EncodedState*> batch;
      std::vector<float> targets;
      for (int i = 0; i < 100; ++i) {
        const auto j = rng.Below(memory.size());
        batch.push_back(&memory[j]);
        targets.push_back(memory_values[j]);
      }
      benchmark::DoNotOptimize(policy.TrainBatch(batch, targets));
    }
  }
  state.counters["steps/episode"] =
      static_cast<double>(steps) / static_cast<double>(state.iterations());
}

void BM_TrainingEpisode(benchmark::State& state) {
  TimeTrainingEpisodes(state, FromArgs(state), RobotKinematics{});
}
BENCHMARK(BM_TrainingEpisode)->Apply(Args)->Unit(benchmark::kMillisecond);

/// The same for lidar+person models as holonomic and as unicycle robots (CrowdNav's unicycle
/// actions, 1 + 2 x 7): within 20% of each other per step (issue 45).
void BM_TrainingEpisodeBody(benchmark::State& state) {
  ValueRlConfig config =
      Config(state.range(0) ? Model::kSarl : Model::kCadrl, SensorSet::kLidarPerson);
  RobotKinematics kinematics;
  if (state.range(1)) {
    config.unicycle_actions = true;
    config.rotation_samples = 7;
    config.stop_action = true;
    kinematics.model = KinematicsModel::kUnicycle;
  }
  TimeTrainingEpisodes(state, config, kinematics);
}
BENCHMARK(BM_TrainingEpisodeBody)
    ->ArgNames({"sarl", "unicycle"})
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({1, 0})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace crowdsim::value_rl
