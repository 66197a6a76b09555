// Neighbour queries of one step for crowds of 5 to 1,000 agents at a constant density (one
// agent per 4 m^2): every agent asks for its 10 nearest within 10 m (ORCA's humans), as an
// episode step does. items_per_second counts agent queries: flat when the cost per agent no
// longer grows with the crowd.
#include <benchmark/benchmark.h>

#include <cmath>

#include "crowdsim/agent_index.h"
#include "crowdsim/rng.h"

namespace crowdsim {
namespace {

void BM_NearestPerAgent(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double side = std::sqrt(4.0 * n);
  Rng rng(7);
  std::vector<AgentState> agents(n);
  for (auto& a : agents) a.position = Vec2(rng.Uniform(0, side), rng.Uniform(0, side));
  AgentIndex index;
  std::vector<int> out;
  for (auto _ : state) {
    index.Rebuild(agents);
    for (int i = 0; i < n; ++i) {
      index.Nearest(agents[i].position, 10.0, 10, i, &out);
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * n);  // agent queries per second
}
BENCHMARK(BM_NearestPerAgent)->Arg(5)->Arg(50)->Arg(200)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim
