// Whole-episode throughput of the CrowdNav task, single thread: suites/crowdnav_orca.yaml's
// first row (ORCA robot with the person sensor, circle crossing of radius 4, 5 ORCA humans,
// CrowdNav's goal rule) exactly as `crowdsim-bench run` plays its episodes: the request of
// episode k, the world's scenario, a new Episode, Run. This is the figure compared with
// CrowdNav's own env (issue 14: >= 150x its episodes per second).
#include <benchmark/benchmark.h>

#include <stdexcept>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/suite.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

void BM_CrowdNavEpisode(benchmark::State& state) {
  PluginRegistry registry({testing::PluginDir()});
  SuiteLoadResult loaded =
      LoadSuite(testing::SourceDir() / "suites" / "crowdnav_orca.yaml", registry);
  if (!loaded.suite) {
    state.SkipWithError(loaded.errors.empty() ? "suite not loaded"
                                              : loaded.errors[0].Format().c_str());
    return;
  }
  const Suite& suite = *loaded.suite;
  const RowSpec& row = suite.rows.at(0);  // label orca
  const auto world = registry.MakeWorld(*row.world.loaded, row.world.params);
  RowInstance instance(row, registry);
  int k = 0;
  std::int64_t steps = 0, successes = 0;
  for (auto _ : state) {
    const Scenario scenario = world->Make(MakeEpisodeRequest(suite, row, *world, k));
    Episode episode(scenario, suite.sim, instance.Agents(scenario.humans.size()));
    const EpisodeResult& result = episode.Run();
    steps += result.steps;
    successes += result.status == EpisodeStatus::kSuccess;
    k = (k + 1) % suite.episodes;  // the suite's 500 episodes, in turn
  }
  const double episodes = static_cast<double>(state.iterations());
  state.counters["episodes_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["steps_per_episode"] = static_cast<double>(steps) / episodes;
  state.counters["success"] = static_cast<double>(successes) / episodes;
}
BENCHMARK(BM_CrowdNavEpisode)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim
