// Episode set-up cost, no steps: the world's scenario (WorldSource::Make: robot trip, human
// placement) and the Episode's construction (Bullet collision world, policy resets, first
// observation), apart and together, as a suite run pays them once per episode. Short
// episodes (CrowdNav's ~30 steps) make these a visible share of a run (issue 14).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "crowdsim/rng.h"
#include "episode_bench.h"

namespace crowdsim {
namespace {

// The worlds of the paper's test suites and of the CrowdNav check, each as a suite row names it.
struct WorldCase {
  std::string plugin;
  std::vector<std::pair<std::string, ParamValue>> params;
  int humans = 5;
};
const WorldCase kRect1{"random_rect",
                       {{"obstacles", std::int64_t{1}}, {"split", std::string("test")}}};
const WorldCase kRect3{"random_rect",
                       {{"obstacles", std::int64_t{3}}, {"split", std::string("test")}}};
const WorldCase kCircle{"crowdnav", {{"scenario", std::string("circle_crossing")}}};
// The paper's hardest floor plan with its 5 humans, and with 50 (beyond what the plan's 400
// free points hold: the rest are drawn from the whole floor).
const WorldCase kGibsonHard{
    "floorplan", {{"file", (testing::SourceDir() / "worlds/gibson/hard.yaml").string()}}};
const WorldCase kGibsonHard50{kGibsonHard.plugin, kGibsonHard.params, 50};

enum class Part { kScenario, kEpisode, kBoth };

// Episode k of a suite with seed 1000 (every layout of the frozen sets is visited in turn).
ScenarioRequest Request(const WorldSource& world, std::int64_t k, int humans) {
  ScenarioRequest request;
  request.seed = DeriveSeed(1000, world.Identity(), static_cast<std::uint64_t>(k % 500));
  request.episode_index = k % 500;
  request.num_humans = humans;
  return request;
}

void BM_EpisodeSetup(benchmark::State& state, const WorldCase& world_case, Part part) {
  bench::RowAgents row(bench::RobotKind::kOrcaLidarPerson, world_case.humans);
  const auto world = row.MakeWorld(world_case.plugin, world_case.params);
  const SimConfig sim;
  std::int64_t k = 0;
  Scenario fixed =
      world->Make(Request(*world, 0, world_case.humans));  // the one kEpisode constructs on
  for (auto _ : state) {
    if (part == Part::kEpisode) {
      Episode episode(fixed, sim, row.agents);
      benchmark::DoNotOptimize(&episode);
    } else {
      const Scenario scenario = world->Make(Request(*world, k++, world_case.humans));
      if (part == Part::kBoth) {
        Episode episode(scenario, sim, row.agents);
        benchmark::DoNotOptimize(&episode);
      }
      benchmark::DoNotOptimize(scenario.humans.data());
    }
  }
}

BENCHMARK_CAPTURE(BM_EpisodeSetup, rect1_scenario, kRect1, Part::kScenario)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, rect1_episode, kRect1, Part::kEpisode)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, rect1_both, kRect1, Part::kBoth)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, rect3_scenario, kRect3, Part::kScenario)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, rect3_episode, kRect3, Part::kEpisode)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, rect3_both, kRect3, Part::kBoth)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, circle_crossing_scenario, kCircle, Part::kScenario)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, circle_crossing_episode, kCircle, Part::kEpisode)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, circle_crossing_both, kCircle, Part::kBoth)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, gibson_hard_scenario, kGibsonHard, Part::kScenario)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EpisodeSetup, gibson_hard_50_scenario, kGibsonHard50, Part::kScenario)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim
