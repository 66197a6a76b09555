// A tiny two-pass crowd simulator over the ORCA solver, for tests and benchmarks: every
// agent computes its new velocity from the same snapshot, then all move (RVO2's doStep).
#pragma once

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/agent_state.h"
#include "orca/obstacles.h"
#include "orca/solver.h"

namespace crowdsim::orca::testing {

/// One simulated agent: its solver state and settings, plus what the scenario drives.
struct SimAgent {
  OrcaAgent state;
  OrcaParams params;
  double neighbor_dist = 15.0;  ///< m
  int max_neighbors = 10;
  Vec2 goal = Vec2::Zero();
  Vec2 pref_velocity = Vec2::Zero();  ///< set by the scenario before each Step
  bool feasible = true;               ///< whether its last solve satisfied every ORCA line
};

/// The preferred velocity of RVO2's examples (and CrowdNav's rule): towards the goal, of unit
/// length when the goal is farther than 1 m.
inline Vec2 TowardsGoal(const SimAgent& agent) {
  const Vec2 d = agent.goal - agent.state.position;
  return d.squaredNorm() > 1.0 ? Vec2(d.normalized()) : d;
}

/// RVO2-like simulation: a neighbour grid rebuilt each step, then compute all, move all.
class TestSim {
 public:
  TestSim(double time_step, OrcaObstacles obstacles)
      : time_step_(time_step), obstacles_(std::move(obstacles)) {}

  /// Adds an agent at rest; returns its index.
  int AddAgent(const SimAgent& agent);

  std::vector<SimAgent>& agents() { return agents_; }
  const std::vector<SimAgent>& agents() const { return agents_; }
  const OrcaObstacles& obstacles() const { return obstacles_; }
  double time() const { return time_; }
  double time_step() const { return time_step_; }

  /// One step with the agents' current preferred velocities.
  void Step();

 private:
  double time_step_;
  OrcaObstacles obstacles_;
  std::vector<SimAgent> agents_;
  double time_ = 0.0;
  // Scratch reused every step.
  std::vector<AgentState> snapshot_;
  AgentIndex index_;
  std::vector<int> ids_;
  std::vector<OrcaAgent> neighbours_;
  OrcaSolveScratch solve_;
  std::vector<Vec2> new_velocities_;
};

/// Smallest centre distance minus radius sum over all pairs (negative: overlap), m. With
/// `feasible_only`, only pairs whose last solves were both feasible count.
double MinPairGap(const std::vector<SimAgent>& agents, bool feasible_only = false);

/// RVO2's Blocks example (reference facts 2.6): 100 agents (radius 2, max speed 2,
/// neighbours 15 m / 10, horizons 5 s) in four groups crossing four 30 x 30 m squares.
TestSim MakeBlocksSim(double time_step);

/// RVO2's Circle example: `agents` agents evenly on a circle of radius `radius` (mirrored in x
/// when asked), each bound for its antipode, with Circle.cc's agent defaults (neighbour dist
/// 15, max neighbours 10, horizons 10 and 10, radius 1.5, max speed 2).
TestSim MakeRvo2Circle(int agents, double radius, double time_step, bool mirror = false);

/// RVO2's RVO_TWO_PI, a float.
inline constexpr float kRvo2TwoPi = 6.28318530717958647692F;

/// A small offset drawn as RVO2's Blocks.cc draws its perturbation, in float: an angle, then a
/// length up to `max_length`, each from one draw of `rng`; the offset from float cosine and sine.
struct Rvo2Offset {
  float x;
  float y;
};
Rvo2Offset DrawRvo2Offset(std::mt19937& rng, float max_length);

/// RVO2's Circle example as Circle.cc builds it: 250 agents (MakeRvo2Circle's defaults), time
/// step 0.25, the starts computed in float32 (angle i * 2 pi * 0.004, then 200 times its cosine
/// and sine), each bound for its antipode. Given `offsets`, every start is first moved by
/// DrawRvo2Offset(*offsets, max_offset), added in float.
TestSim MakeRvo2FloatCircle(std::mt19937* offsets = nullptr, float max_offset = 0.0F);

/// Every agent within `distance(agent)` of its goal (RVO2's reachedGoal).
template <typename Distance>
bool AllWithin(const TestSim& sim, Distance distance) {
  return std::all_of(sim.agents().begin(), sim.agents().end(), [&](const SimAgent& a) {
    const double r = distance(a);
    return (a.state.position - a.goal).squaredNorm() <= r * r;
  });
}

/// The four squares of Blocks as rectangles (for inside-obstacle checks).
std::vector<Rect> BlocksSquares();

}  // namespace crowdsim::orca::testing
