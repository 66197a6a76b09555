// Social force costs: one decision of the loaded plugin for a human with 10 neighbours and 7
// rectangles (neighbour query, guidance, forces, the slide along edges).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "human_decision.h"

namespace crowdsim {
namespace {

void BM_SocialForceDecide10Neighbours7Rects(benchmark::State& state) {
  std::vector<AgentState> others;
  for (int k = 0; k < 10; ++k) {  // ten people on a ring 1.2-3 m away, walking across
    const double a = 0.63 * k;
    AgentState s;
    s.position = (1.2 + 0.18 * k) * Vec2(std::cos(a), std::sin(a));
    s.velocity = 0.8 * Vec2(-std::sin(a), std::cos(a));
    others.push_back(s);
  }
  bench::TimeHumanDecision(state, "social_force", others);
}
BENCHMARK(BM_SocialForceDecide10Neighbours7Rects);

}  // namespace
}  // namespace crowdsim
