// One decision of a loaded humans' policy, as the harness asks it: the scene the ORCA and the
// social force benchmarks both time (seven rectangles, the goal behind one). Header-only.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/bench/plugin_registry.h"
#include "test_paths.h"

namespace crowdsim::bench {

/// Seven rectangles within obstacle range (5.3 m) of an agent at the origin.
inline std::vector<Rect> SevenRects() {
  return {Rect::FromCorners(1.5, -0.5, 2.5, 1.0),   Rect::FromCorners(-3.0, 1.0, -1.5, 2.0),
          Rect::FromCorners(-1.0, -3.5, 1.0, -2.5), Rect::FromCorners(3.0, 2.5, 4.5, 4.0),
          Rect::FromCorners(-4.5, -2.0, -3.5, 0.0), Rect::FromCorners(2.5, -4.0, 4.0, -3.0),
          Rect::FromCorners(-1.0, 3.5, 1.0, 4.5)};
}

/// Ten people on a ring 1.2-3 m around the origin, walking across it at 0.8 m/s.
inline std::vector<AgentState> TenCrossingPeople() {
  std::vector<AgentState> others;
  for (int k = 0; k < 10; ++k) {
    const double a = 0.63 * k;
    AgentState s;
    s.position = (1.2 + 0.18 * k) * Vec2(std::cos(a), std::sin(a));
    s.velocity = 0.8 * Vec2(-std::sin(a), std::cos(a));
    others.push_back(s);
  }
  return others;
}

/// Times `plugin`'s Decide (schema defaults) for a human at the origin, heading for a goal
/// behind a rectangle (guidance has a path to follow), among `others` and SevenRects().
inline void TimeHumanDecision(benchmark::State& state, const std::string& plugin,
                              const std::vector<AgentState>& others) {
  PluginRegistry registry({testing::PluginDir()});
  const LoadedPlugin& loaded = registry.Load(plugin, PluginKind::kPolicy);
  auto policy = registry.MakePolicy(loaded, Params::Defaults(loaded.schema));
  StaticMap map;
  map.bounds = Rect::FromCorners(-10, -10, 10, 10);
  map.rectangles = SevenRects();
  EpisodeContext ctx;
  ctx.map = &map;
  ctx.role = AgentRole::kHuman;
  policy->Reset(ctx);
  std::vector<AgentState> agents(1);
  agents[0].position = Vec2::Zero();
  agents[0].velocity = Vec2(0.8, 0.2);
  agents[0].goal = Vec2(6.0, -1.0);
  agents.insert(agents.end(), others.begin(), others.end());
  AgentIndex index;
  index.Rebuild(agents);
  Observation obs;
  obs.self = agents[0];
  obs.agents = &index;
  obs.self_index = 0;
  for (auto _ : state) benchmark::DoNotOptimize(policy->Decide(obs));
}

}  // namespace crowdsim::bench
