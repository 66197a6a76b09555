// Headed social force costs: one decision of the loaded plugin for a human with 10 neighbours
// and 7 rectangles (neighbour query, guidance, ten sub-steps of forces and torque, the slide).
#include <benchmark/benchmark.h>

#include "human_decision.h"

namespace crowdsim {
namespace {

void BM_HsfmDecide10Neighbours7Rects(benchmark::State& state) {
  bench::TimeHumanDecision(state, "hsfm", bench::TenCrossingPeople());
}
BENCHMARK(BM_HsfmDecide10Neighbours7Rects);

}  // namespace
}  // namespace crowdsim
