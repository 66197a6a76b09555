// Whole-episode throughput of the CrowdNav task, single thread: suites/crowdnav_orca.yaml's
// first row (ORCA robot with the person sensor, circle crossing of radius 4, 5 ORCA humans,
// CrowdNav's goal rule) exactly as `crowdsim-bench run` plays its episodes: the request of
// episode k, the world's scenario, a new Episode, Run. This is the figure compared with
// CrowdNav's own env (issue 14: >= 150x its episodes per second).
//
// Where that time goes, exactly: the same 500 episodes with some agents' decisions replayed
// (each action as the real policy chose it in that episode and step), so the episodes, their
// steps and outcomes are the ones of the real run and only the replayed decisions' cost is
// gone. Each policy then sits behind a recorder (a call and a store per decision), so the
// split is taken against BM_CrowdNavEpisodeReplaying/nobody, the recorders recording:
// .../nobody less .../humans is what the five humans' decisions cost, less .../robot the
// robot's, and .../everybody is everything else: the scenario, the episode's set-up, the
// neighbour index, the robot's observation, the collision test, rewards and records (and the
// recorders' replay). BM_CrowdNavEpisode plays the row's own policies, no recorder between. (Timing
// a part by doing it twice per step underestimates it: the second call repeats the first's branches
// and finds its data in cache.) BM_CrowdNavEpisodeSocialMetrics adds the social navigation metrics.
#include <benchmark/benchmark.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/play_episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/suite.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

// A policy that either decides with the policy it wraps and records the actions, or plays
// back what it recorded for the same episode, step by step, without deciding.
class RecordedPolicy final : public Policy {
 public:
  explicit RecordedPolicy(Policy* real) : real_(real) {}
  PolicyNeeds Needs() const override { return real_->Needs(); }
  void Reset(const EpisodeContext& ctx) override {
    if (!replaying_) {
      real_->Reset(ctx);
      actions_[episode_].clear();
    }
    step_ = 0;
  }
  Action Decide(const Observation& obs) override {
    std::vector<Action>& actions = actions_[episode_];
    if (!replaying_) return actions.emplace_back(real_->Decide(obs));
    if (step_ >= actions.size()) throw std::logic_error("replay ran past the recorded actions");
    return actions[step_++];
  }
  void Use(int episode, bool replaying) {
    episode_ = static_cast<size_t>(episode);
    replaying_ = replaying;
  }
  void SizeFor(int episodes) { actions_.resize(static_cast<size_t>(episodes)); }

 private:
  Policy* real_;
  std::vector<std::vector<Action>> actions_;  // per episode, per step
  size_t episode_ = 0;
  size_t step_ = 0;
  bool replaying_ = false;
};

enum class Replayed { kNobody, kHumans, kRobot, kEverybody };

// The suite's first row and its 500 episodes, each played once for real to record its actions.
class CrowdNavTask {
 public:
  CrowdNavTask() {
    loaded_ = LoadSuite(testing::SourceDir() / "suites" / "crowdnav_orca.yaml", registry_);
    if (!loaded_.suite) {
      throw std::runtime_error(loaded_.errors.empty() ? "suite not loaded"
                                                      : loaded_.errors[0].Format());
    }
    const RowSpec& row = suite().rows.at(0);  // label orca
    world_ = registry_.MakeWorld(*row.world.loaded, row.world.params);
    instance_ = std::make_unique<RowInstance>(row, registry_);
    agents_ = instance_->Agents(static_cast<size_t>(row.humans.count_max));
    plain_agents_ = agents_;
    // The row with its person sensor made realistic (perception.yaml's cell), then tracked.
    for (const bool tracked : {false, true}) {
      RowSpec real = row;
      Params& person = real.sensors.at(0).params;
      person.Set("fov_deg", 180.0);
      person.Set("occlusion", std::string("obstacles+people"));
      person.Set("position_noise", 0.1);
      person.Set("detection_prob", 0.9);
      if (tracked) {
        person.Set("false_detections", 0.5);
        person.Set("velocity", std::string("estimated"));
        person.Set("tracker", std::string("nearest"));
      }
      perceiving_.push_back(std::make_unique<RowInstance>(real, registry_));
      perceiving_agents_.push_back(
          perceiving_.back()->Agents(static_cast<size_t>(row.humans.count_max)));
    }
    robot_ = std::make_unique<RecordedPolicy>(agents_.robot);
    agents_.robot = robot_.get();
    for (Policy*& human : agents_.humans) {
      humans_.push_back(std::make_unique<RecordedPolicy>(human));
      human = humans_.back().get();
    }
    robot_->SizeFor(episodes());
    for (auto& h : humans_) h->SizeFor(episodes());
    for (int k = 0; k < episodes(); ++k) recorded_.push_back(Play(k, Replayed::kNobody));
  }

  int episodes() const { return suite().episodes; }
  const Suite& suite() const { return *loaded_.suite; }
  const EpisodeResult& Recorded(int k) const { return recorded_[static_cast<size_t>(k)]; }

  /// Episode k as a suite run plays it: the row's own policies, nothing between them and the
  /// episode; with the social metrics when `social`.
  EpisodeOutcome PlayPlain(int k, MetricFamilies social) {
    const RowSpec& row = suite().rows.at(0);
    const Scenario scenario = world_->Make(MakeEpisodeRequest(suite(), row, *world_, k));
    Episode episode(scenario, suite().sim, plain_agents_);
    return PlayEpisode(episode, social);
  }

  /// Episode k with the realistic person sensor (`tracked`: with phantoms, tracker, velocities).
  EpisodeOutcome PlayPerceiving(int k, bool tracked) {
    const RowSpec& row = suite().rows.at(0);
    const Scenario scenario = world_->Make(MakeEpisodeRequest(suite(), row, *world_, k));
    Episode episode(scenario, suite().sim, perceiving_agents_.at(tracked ? 1 : 0));
    return episode.Run();
  }

  /// Episode k with every policy behind its recorder, the decisions of `replayed` played back.
  EpisodeResult Play(int k, Replayed replayed) {
    robot_->Use(k, replayed == Replayed::kRobot || replayed == Replayed::kEverybody);
    for (auto& h : humans_) {
      h->Use(k, replayed == Replayed::kHumans || replayed == Replayed::kEverybody);
    }
    const RowSpec& row = suite().rows.at(0);
    const Scenario scenario = world_->Make(MakeEpisodeRequest(suite(), row, *world_, k));
    Episode episode(scenario, suite().sim, agents_);
    return episode.Run();
  }

 private:
  PluginRegistry registry_{{testing::PluginDir()}};
  SuiteLoadResult loaded_;
  std::shared_ptr<WorldSource> world_;
  std::unique_ptr<RowInstance> instance_;
  EpisodeAgents agents_;                                  // the recorders
  EpisodeAgents plain_agents_;                            // the row's policies themselves
  std::vector<std::unique_ptr<RowInstance>> perceiving_;  // realistic, realistic + tracked
  std::vector<EpisodeAgents> perceiving_agents_;
  std::unique_ptr<RecordedPolicy> robot_;
  std::vector<std::unique_ptr<RecordedPolicy>> humans_;
  std::vector<EpisodeResult> recorded_;
};

// `replayed` empty: the plain episodes, as `crowdsim-bench run` plays them (with the social
// metrics when `social`).
void TimeEpisodes(benchmark::State& state, std::optional<Replayed> replayed,
                  MetricFamilies social = 0) {
  static CrowdNavTask* task = nullptr;  // recorded once for every variant
  try {
    if (task == nullptr) task = new CrowdNavTask();
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  int k = 0;
  std::int64_t steps = 0, successes = 0;
  for (auto _ : state) {
    const EpisodeOutcome result = replayed ? task->Play(k, *replayed) : task->PlayPlain(k, social);
    // A replay must be the recorded episode; anything else would time another workload.
    if (result.steps != task->Recorded(k).steps || result.status != task->Recorded(k).status) {
      state.SkipWithError("a replayed episode differs from the recorded one");
      return;
    }
    steps += result.steps;
    successes += result.status == EpisodeStatus::kSuccess;
    k = (k + 1) % task->episodes();  // the suite's 500 episodes, in turn
  }
  const double episodes = static_cast<double>(state.iterations());
  state.counters["episodes_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["steps_per_episode"] = static_cast<double>(steps) / episodes;
  state.counters["success"] = static_cast<double>(successes) / episodes;
}
void BM_CrowdNavEpisode(benchmark::State& state) { TimeEpisodes(state, std::nullopt); }
BENCHMARK(BM_CrowdNavEpisode)->Unit(benchmark::kMicrosecond);

// The same episodes with every social navigation metric computed (issue 47: within 10%).
void BM_CrowdNavEpisodeSocialMetrics(benchmark::State& state) {
  TimeEpisodes(state, std::nullopt, kCoreMetrics);
}
BENCHMARK(BM_CrowdNavEpisodeSocialMetrics)->Unit(benchmark::kMicrosecond);

// And the robot's effect on the people, which replays each episode without the robot (opt-in).
void BM_CrowdNavEpisodePeopleEffect(benchmark::State& state) {
  TimeEpisodes(state, std::nullopt, kCoreMetrics | kEffectMetrics);
}
BENCHMARK(BM_CrowdNavEpisodePeopleEffect)->Unit(benchmark::kMicrosecond);

// The row with a realistic person sensor (its own episodes: see the top).
void BM_CrowdNavEpisodePerception(benchmark::State& state, bool tracked) {
  static CrowdNavTask* task = nullptr;
  try {
    if (task == nullptr) task = new CrowdNavTask();
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  int k = 0;
  std::int64_t steps = 0;
  for (auto _ : state) {
    steps += task->PlayPerceiving(k, tracked).steps;
    k = (k + 1) % task->episodes();
  }
  state.counters["episodes_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["steps_per_episode"] =
      static_cast<double>(steps) / static_cast<double>(state.iterations());
  state.counters["time_per_step"] = benchmark::Counter(
      static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_CrowdNavEpisodePerception, realistic, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CrowdNavEpisodePerception, realistic_tracked, true)
    ->Unit(benchmark::kMicrosecond);

void BM_CrowdNavEpisodeReplaying(benchmark::State& state, Replayed replayed) {
  TimeEpisodes(state, replayed);
}
// The split's baseline: every policy behind its recorder, recording (nothing replayed).
BENCHMARK_CAPTURE(BM_CrowdNavEpisodeReplaying, nobody, Replayed::kNobody)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CrowdNavEpisodeReplaying, humans, Replayed::kHumans)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CrowdNavEpisodeReplaying, robot, Replayed::kRobot)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CrowdNavEpisodeReplaying, everybody, Replayed::kEverybody)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim
