// One run of RVO2's Circle or Blocks example on our ORCA solver with a seeded perturbation,
// for paired overlap statistics against RVO2's C++ (tests/bench/orca/overlap_stats.sh, whose
// RVO2 driver draws the same numbers in the same order from the same generator).
//
//   rvo2_overlap_stats circle|blocks SEED
//
// Blocks: rvo2_scenarios_bench's PreferBlocks with std::mt19937(SEED). Circle: RVO2's float32
// starts, each offset (in float) by up to 0.01 m in a random direction drawn from
// std::mt19937(SEED) as PreferBlocks draws (angle, then length); SEED 0 leaves the starts as
// they are. Goals are the antipodes of the offset starts; no velocity perturbation.
// Runs until every agent arrived (the example's test) or 10,000 steps. After every step, each
// agent pair whose centre distance is below its radius sum is one violation, with a depth of
// radius sum - distance. Prints one line:
//   steps=N all_arrived=0|1 worst_overlap_m=X violations=N overlap_m_steps=X
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "orca_test_sim.h"

namespace crowdsim::orca {
namespace {

using testing::SimAgent;
using testing::TestSim;
using testing::TowardsGoal;

constexpr int kMaxSteps = 10000;

struct Stats {
  int steps = 0;
  bool arrived = false;
  double worst = 0.0;  // m
  long violations = 0;
  double depth_sum = 0.0;  // m x steps
};

void CountOverlaps(const std::vector<SimAgent>& agents, Stats& stats) {
  for (std::size_t i = 0; i < agents.size(); ++i) {
    for (std::size_t j = i + 1; j < agents.size(); ++j) {
      const double depth = agents[i].state.radius + agents[j].state.radius -
                           (agents[i].state.position - agents[j].state.position).norm();
      if (depth > 0.0) {
        ++stats.violations;
        stats.depth_sum += depth;
        stats.worst = std::max(stats.worst, depth);
      }
    }
  }
}

int Main(int argc, char** argv) {
  const std::string scenario = argc == 3 ? argv[1] : "";
  if (scenario != "circle" && scenario != "blocks") {
    std::fprintf(stderr, "usage: rvo2_overlap_stats circle|blocks SEED\n");
    return 2;
  }
  const auto seed = static_cast<unsigned>(std::strtoul(argv[2], nullptr, 10));
  const bool circle = scenario == "circle";
  std::mt19937 rng(seed);  // Circle's start offsets, or Blocks' per-step perturbation
  TestSim sim = !circle     ? testing::MakeBlocksSim(0.25)
                : seed == 0 ? testing::MakeRvo2FloatCircle()
                            : testing::MakeRvo2FloatCircle(&rng, 0.01F);
  auto arrive_distance = [circle](const SimAgent& a) { return circle ? a.state.radius : 20.0; };
  Stats stats;
  while (!(stats.arrived = testing::AllWithin(sim, arrive_distance)) && stats.steps < kMaxSteps) {
    for (SimAgent& a : sim.agents()) {
      a.pref_velocity = TowardsGoal(a);
      if (circle) continue;
      const testing::Rvo2Offset offset = testing::DrawRvo2Offset(rng, 0.0001F);
      a.pref_velocity += Vec2(offset.x, offset.y);
    }
    sim.Step();
    ++stats.steps;
    CountOverlaps(sim.agents(), stats);
  }
  std::printf("steps=%d all_arrived=%d worst_overlap_m=%.6f violations=%ld overlap_m_steps=%.6f\n",
              stats.steps, stats.arrived ? 1 : 0, stats.worst, stats.violations, stats.depth_sum);
  return 0;
}

}  // namespace
}  // namespace crowdsim::orca

int main(int argc, char** argv) { return crowdsim::orca::Main(argc, argv); }
