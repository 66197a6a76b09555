// Replayed crowds (issue 46's target: O(people present) per step): one Episode::Step of a
// recorded ETH/UCY scene, suites/replay.yaml's set-up (the `crowds` world on a scene's test
// windows, every person moved by `replay`), the robot standing still and sensing nothing, so
// the step is the recorded people's alone. Each measured episode is the scene's next window.
//
// per_present_step (CPU time over the people present) should stay flat from the sparsest scene
// to the busiest (univ1, up to 95 present), and the slots of people never present (humans.count
// beyond a window's crowd, 120 in suites/replay.yaml) should cost next to nothing: /slots:480
// against /slots:120.
#include <benchmark/benchmark.h>

#include <string>

#include "episode_bench.h"

namespace crowdsim {
namespace {

void BM_ReplayStep(benchmark::State& state, const char* scene) {
  const int slots = static_cast<int>(state.range(0));
  bench::RowAgents row(bench::RobotKind::kStill, slots, "replay");
  const std::string file =
      (testing::SourceDir() / "worlds" / "crowds" / (std::string(scene) + ".tracks")).string();
  const auto world = row.MakeWorld("crowds", {{"file", file}, {"split", std::string("test")}});
  // A window lasts 25 s: each measured episode is one whole window but its last 5 s.
  bench::TimeSteps(state, bench::SuiteScenarios(*world, 2026, slots), row.agents, slots);
}

void Slots(benchmark::internal::Benchmark* b) {
  b->ArgName("slots")->Arg(120)->Unit(benchmark::kMicrosecond);
}

BENCHMARK_CAPTURE(BM_ReplayStep, zara1, "zara1")->Apply(Slots);
BENCHMARK_CAPTURE(BM_ReplayStep, hotel, "hotel")->Apply(Slots);
BENCHMARK_CAPTURE(BM_ReplayStep, eth, "eth")->Apply(Slots);
BENCHMARK_CAPTURE(BM_ReplayStep, zara2, "zara2")->Apply(Slots);
BENCHMARK_CAPTURE(BM_ReplayStep, univ3, "univ3")->Apply(Slots);
BENCHMARK_CAPTURE(BM_ReplayStep, univ1, "univ1")->Apply(Slots)->Arg(480);

}  // namespace
}  // namespace crowdsim
