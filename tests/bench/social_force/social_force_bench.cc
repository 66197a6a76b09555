// Social force costs: one decision of the loaded plugin for a human with 10 neighbours and 7
// rectangles (neighbour query, guidance, forces, the slide along edges).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/bench/plugin_registry.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

void BM_SocialForceDecide10Neighbours7Rects(benchmark::State& state) {
  PluginRegistry registry({crowdsim::testing::PluginDir()});
  const LoadedPlugin& plugin = registry.Load("social_force", PluginKind::kPolicy);
  auto policy = registry.MakePolicy(plugin, Params::Defaults(plugin.schema));
  StaticMap map;
  map.bounds = Rect::FromCorners(-10, -10, 10, 10);
  // The seven rectangles of the ORCA benchmark (orca_bench.cc).
  map.rectangles = {
      Rect::FromCorners(1.5, -0.5, 2.5, 1.0),   Rect::FromCorners(-3.0, 1.0, -1.5, 2.0),
      Rect::FromCorners(-1.0, -3.5, 1.0, -2.5), Rect::FromCorners(3.0, 2.5, 4.5, 4.0),
      Rect::FromCorners(-4.5, -2.0, -3.5, 0.0), Rect::FromCorners(2.5, -4.0, 4.0, -3.0),
      Rect::FromCorners(-1.0, 3.5, 1.0, 4.5)};
  EpisodeContext ctx;
  ctx.map = &map;
  ctx.role = AgentRole::kHuman;
  policy->Reset(ctx);
  std::vector<AgentState> agents(1);
  agents[0].position = Vec2::Zero();
  agents[0].velocity = Vec2(0.8, 0.2);
  agents[0].goal = Vec2(6.0, -1.0);  // behind a rectangle: guidance has a path to follow
  for (int k = 0; k < 10; ++k) {     // ten people on a ring 1.2-3 m away, walking across
    const double a = 0.63 * k;
    AgentState s;
    s.position = (1.2 + 0.18 * k) * Vec2(std::cos(a), std::sin(a));
    s.velocity = 0.8 * Vec2(-std::sin(a), std::cos(a));
    agents.push_back(s);
  }
  AgentIndex index;
  index.Rebuild(agents);
  Observation obs;
  obs.self = agents[0];
  obs.agents = &index;
  obs.self_index = 0;
  for (auto _ : state) benchmark::DoNotOptimize(policy->Decide(obs));
}
BENCHMARK(BM_SocialForceDecide10Neighbours7Rects);

}  // namespace
}  // namespace crowdsim
