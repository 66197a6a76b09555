// Social force costs: one decision of the loaded plugin for a human with 10 neighbours and 7
// rectangles (neighbour query, guidance, forces, the slide along edges).
#include <benchmark/benchmark.h>

#include "human_decision.h"

namespace crowdsim {
namespace {

void BM_SocialForceDecide10Neighbours7Rects(benchmark::State& state) {
  bench::TimeHumanDecision(state, "social_force", bench::TenCrossingPeople());
}
BENCHMARK(BM_SocialForceDecide10Neighbours7Rects);

}  // namespace
}  // namespace crowdsim
