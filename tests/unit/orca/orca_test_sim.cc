#include "orca_test_sim.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace crowdsim::orca::testing {

int TestSim::AddAgent(const SimAgent& agent) {
  agents_.push_back(agent);
  return static_cast<int>(agents_.size()) - 1;
}

void TestSim::Step() {
  const std::size_t n = agents_.size();
  snapshot_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    snapshot_[i].position = agents_[i].state.position;
    snapshot_[i].velocity = agents_[i].state.velocity;
    snapshot_[i].radius = agents_[i].state.radius;
  }
  index_.Rebuild(snapshot_);
  new_velocities_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SimAgent& a = agents_[i];
    index_.Nearest(a.state.position, a.neighbor_dist, a.max_neighbors, static_cast<int>(i), &ids_);
    neighbours_.clear();
    for (int id : ids_) neighbours_.push_back(agents_[id].state);
    OrcaSolveInfo info;  // the solve with the caller's scratch, as the orca plugin's
    new_velocities_[i] = ComputeOrcaVelocity(a.state, neighbours_, obstacles_, a.params,
                                             a.pref_velocity, time_step_, &solve_, &info);
    agents_[i].feasible = info.feasible;
  }
  for (std::size_t i = 0; i < n; ++i) {
    agents_[i].state.velocity = new_velocities_[i];
    agents_[i].state.position += new_velocities_[i] * time_step_;
  }
  time_ += time_step_;
}

double MinPairGap(const std::vector<SimAgent>& agents, bool feasible_only) {
  double gap = kInfinity;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    for (std::size_t j = i + 1; j < agents.size(); ++j) {
      if (feasible_only && !(agents[i].feasible && agents[j].feasible)) continue;
      const double d = (agents[i].state.position - agents[j].state.position).norm();
      gap = std::min(gap, d - agents[i].state.radius - agents[j].state.radius);
    }
  }
  return gap;
}

namespace {

// Counter-clockwise, as RVO2's example adds them.
const std::array<std::array<Vec2, 4>, 4> kBlocksSquares = {{
    {Vec2(-10, 40), Vec2(-40, 40), Vec2(-40, 10), Vec2(-10, 10)},
    {Vec2(10, 40), Vec2(10, 10), Vec2(40, 10), Vec2(40, 40)},
    {Vec2(10, -40), Vec2(40, -40), Vec2(40, -10), Vec2(10, -10)},
    {Vec2(-10, -40), Vec2(-10, -10), Vec2(-40, -10), Vec2(-40, -40)},
}};

}  // namespace

std::vector<Rect> BlocksSquares() {
  std::vector<Rect> boxes;
  for (const auto& square : kBlocksSquares) {
    Rect box{square[0], square[0]};
    for (const Vec2& v : square) {
      box.min = box.min.cwiseMin(v);
      box.max = box.max.cwiseMax(v);
    }
    boxes.push_back(box);
  }
  return boxes;
}

TestSim MakeBlocksSim(double time_step) {
  OrcaObstacles obstacles;
  for (const auto& square : kBlocksSquares) obstacles.AddPolygon(square);
  TestSim sim(time_step, std::move(obstacles));
  auto add = [&](const Vec2& start, const Vec2& goal) {
    SimAgent agent;  // setAgentDefaults(15, 10, 5, 5, 2, 2)
    agent.neighbor_dist = 15.0;
    agent.max_neighbors = 10;
    agent.params = OrcaParams{5.0, 5.0, 2.0};
    agent.state.radius = 2.0;
    agent.state.position = start;
    agent.goal = goal;
    sim.AddAgent(agent);
  };
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      add(Vec2(55.0 + 10 * i, 55.0 + 10 * j), Vec2(-75, -75));
      add(Vec2(-55.0 - 10 * i, 55.0 + 10 * j), Vec2(75, -75));
      add(Vec2(55.0 + 10 * i, -55.0 - 10 * j), Vec2(-75, 75));
      add(Vec2(-55.0 - 10 * i, -55.0 - 10 * j), Vec2(75, 75));
    }
  }
  return sim;
}

TestSim MakeRvo2Circle(int agents, double radius, double time_step, bool mirror) {
  TestSim sim(time_step, OrcaObstacles());
  for (int i = 0; i < agents; ++i) {
    const double a = i * 2.0 * std::numbers::pi / agents;
    SimAgent agent;
    agent.neighbor_dist = 15.0;
    agent.max_neighbors = 10;
    agent.params = OrcaParams{10.0, 10.0, 2.0};
    agent.state.radius = 1.5;
    agent.state.position = radius * Vec2(std::cos(a), std::sin(a));
    if (mirror) agent.state.position.x() = -agent.state.position.x();
    agent.goal = -agent.state.position;
    sim.AddAgent(agent);
  }
  return sim;
}

Rvo2Offset DrawRvo2Offset(std::mt19937& rng, float max_length) {
  constexpr float kDrawMax = static_cast<float>(std::mt19937::max());
  const float angle = static_cast<float>(rng()) * kRvo2TwoPi / kDrawMax;
  const float length = static_cast<float>(rng()) * max_length / kDrawMax;
  return {length * std::cos(angle), length * std::sin(angle)};
}

TestSim MakeRvo2FloatCircle(std::mt19937* offsets, float max_offset) {
  TestSim sim = MakeRvo2Circle(250, 200.0, 0.25);
  for (std::size_t i = 0; i < sim.agents().size(); ++i) {
    const float angle = static_cast<float>(i) * kRvo2TwoPi * 0.004F;
    float x = 200.0F * std::cos(angle);
    float y = 200.0F * std::sin(angle);
    if (offsets != nullptr) {
      const Rvo2Offset offset = DrawRvo2Offset(*offsets, max_offset);
      x += offset.x;
      y += offset.y;
    }
    sim.agents()[i].state.position = Vec2(x, y);
    sim.agents()[i].goal = -Vec2(x, y);
  }
  return sim;
}

}  // namespace crowdsim::orca::testing
