// A random scene for the property tests of force-model people (social_force, hsfm): four
// rectangles in a 10 m square, a start and a goal 0.05 m clear of them, and a walk through
// it. Header-only.
#pragma once

#include <random>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/agent_state.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/static_map.h"

namespace crowdsim::testing {

struct WalkScene {
  StaticMap map;
  AgentState self;  ///< radius 0.3 m, v_pref 1 m/s, standing
};

/// Draws the rectangles, then the start, then the goal from `rng`.
inline WalkScene RandomWalkScene(std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-5.0, 5.0), size(0.3, 2.5);
  WalkScene scene;
  scene.map.bounds = Rect::FromCorners(-8, -8, 8, 8);
  for (int r = 0; r < 4; ++r) {
    const Vec2 corner(coord(rng), coord(rng));
    scene.map.rectangles.push_back(Rect{corner, corner + Vec2(size(rng), size(rng))});
  }
  scene.self.radius = 0.3;
  scene.self.v_pref = 1.0;
  const auto clear = [&](const Vec2& p) {
    for (const Rect& rect : scene.map.rectangles) {
      if ((p - p.cwiseMax(rect.min).cwiseMin(rect.max)).norm() < scene.self.radius + 0.05)
        return false;
    }
    return true;
  };
  do scene.self.position = Vec2(coord(rng), coord(rng));
  while (!clear(scene.self.position));
  do scene.self.goal = Vec2(coord(rng), coord(rng));
  while (!clear(scene.self.goal));
  return scene;
}

// Runs the loaded plugin with `params` for one person `self` alone on `map` for `steps`
// decisions, calling `check` with the velocity and the state after each.
template <typename Check>
void Walk(const LoadedPlugin& plugin, PluginRegistry& registry, const Params& params,
          const StaticMap* map, AgentState self, int steps, Check check) {
  auto policy = registry.MakePolicy(plugin, params);
  EpisodeContext ctx;
  ctx.map = map;
  ctx.role = AgentRole::kHuman;
  policy->Reset(ctx);
  std::vector<AgentState> agents{self};
  AgentIndex index;
  for (int step = 0; step < steps; ++step) {
    index.Rebuild(agents);
    Observation obs;
    obs.self = agents[0];
    obs.agents = &index;
    obs.self_index = 0;
    const Vec2 v = policy->Decide(obs).velocity;
    agents[0].position += v * ctx.sim.time_step;
    agents[0].velocity = v;
    check(step, v, agents[0]);
  }
}

}  // namespace crowdsim::testing
