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

constexpr float kTwoPi = 6.28318530717958647692F;  // RVO2's RVO_TWO_PI, a float
constexpr float kDrawMax = static_cast<float>(std::mt19937::max());
constexpr int kMaxSteps = 10000;

struct FloatOffset {
  float x, y;
};

// A float offset of length up to `max_length` in a random direction: angle, then length.
FloatOffset DrawOffset(std::mt19937& rng, float max_length) {
  const float angle = static_cast<float>(rng()) * kTwoPi / kDrawMax;
  const float length = static_cast<float>(rng()) * max_length / kDrawMax;
  return {length * std::cos(angle), length * std::sin(angle)};
}

TestSim MakeCircle(unsigned seed) {
  std::mt19937 rng(seed);
  TestSim sim = testing::MakeRvo2Circle(250, 200.0, 0.25);
  for (std::size_t i = 0; i < sim.agents().size(); ++i) {
    const float angle = static_cast<float>(i) * kTwoPi * 0.004F;
    float x = 200.0F * std::cos(angle);
    float y = 200.0F * std::sin(angle);
    if (seed != 0) {
      const FloatOffset offset = DrawOffset(rng, 0.01F);
      x += offset.x;  // float sums, as RVO2's Vector2 adds
      y += offset.y;
    }
    sim.agents()[i].state.position = Vec2(x, y);
    sim.agents()[i].goal = -Vec2(x, y);
  }
  return sim;
}

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

// Every agent within `radius` of its goal, or within its own radius when `radius` < 0.
bool AllWithin(const TestSim& sim, double radius) {
  for (const SimAgent& a : sim.agents()) {
    const double r = radius < 0.0 ? a.state.radius : radius;
    if ((a.state.position - a.goal).squaredNorm() > r * r) return false;
  }
  return true;
}

int Main(int argc, char** argv) {
  const std::string scenario = argc == 3 ? argv[1] : "";
  if (scenario != "circle" && scenario != "blocks") {
    std::fprintf(stderr, "usage: rvo2_overlap_stats circle|blocks SEED\n");
    return 2;
  }
  const auto seed = static_cast<unsigned>(std::strtoul(argv[2], nullptr, 10));
  const bool circle = scenario == "circle";
  TestSim sim = circle ? MakeCircle(seed) : testing::MakeBlocksSim(0.25);
  const double arrive_radius = circle ? -1.0 : 20.0;
  std::mt19937 rng(seed);  // Blocks' per-step perturbation
  Stats stats;
  while (!(stats.arrived = AllWithin(sim, arrive_radius)) && stats.steps < kMaxSteps) {
    for (SimAgent& a : sim.agents()) {
      a.pref_velocity = TowardsGoal(a);
      if (circle) continue;
      const FloatOffset offset = DrawOffset(rng, 0.0001F);
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
