// Neighbour queries of one step for crowds of 5 to 1,000 agents at a constant density (one
// agent per 4 m^2): every agent asks for its 10 nearest within 10 m (ORCA's humans), as an
// episode step does. items_per_second counts agent queries: flat when the cost per agent no
// longer grows with the crowd.
//
// Each iteration takes the next of 128 prepared frames in which every agent stands up to
// 0.25 m in x and y from its home (a step of CrowdNav's humans), so the grid and the queries
// differ from one iteration to the next. With agents that stand
// still, the same queries repeat exactly and the processor's branch predictor learns their
// outcomes: on the 2-core AMD EPYC (Zen 4) development VM the still crowd of 1,000 ran its
// queries 2.8x faster (157 against 439 us a step) than a crowd that moves, and an episode's
// queries cost what the moving crowd's do. `still` keeps that case to show the difference.
#include <benchmark/benchmark.h>

#include <cmath>

#include "crowdsim/agent_index.h"
#include "crowdsim/rng.h"

namespace crowdsim {
namespace {

void BM_NearestPerAgent(benchmark::State& state, bool move) {
  const int n = static_cast<int>(state.range(0));
  const double side = std::sqrt(4.0 * n);
  Rng rng(7);
  std::vector<AgentState> home(n);
  for (auto& a : home) a.position = Vec2(rng.Uniform(0, side), rng.Uniform(0, side));
  std::vector<std::vector<AgentState>> frames(move ? 128 : 1, home);
  for (auto& frame : frames) {
    for (auto& a : frame) a.position += Vec2(rng.Uniform(-0.25, 0.25), rng.Uniform(-0.25, 0.25));
  }
  if (!move) frames[0] = home;
  AgentIndex index;
  std::vector<int> out;
  std::size_t next = 0;
  for (auto _ : state) {
    const std::vector<AgentState>& agents = frames[next];
    next = (next + 1) % frames.size();
    index.Rebuild(agents);
    for (int i = 0; i < n; ++i) {
      index.Nearest(agents[i].position, 10.0, 10, i, &out);
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * n);  // agent queries per second
}
BENCHMARK_CAPTURE(BM_NearestPerAgent, moving, true)
    ->Arg(5)
    ->Arg(16)
    ->Arg(50)
    ->Arg(200)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NearestPerAgent, still, false)
    ->Arg(50)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim
