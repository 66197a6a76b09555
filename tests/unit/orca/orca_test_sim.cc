#include "orca_test_sim.h"

#include <algorithm>

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
    OrcaSolveInfo info;
    new_velocities_[i] = ComputeOrcaVelocity(a.state, neighbours_, obstacles_, a.params,
                                             a.pref_velocity, time_step_, &info);
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

}  // namespace crowdsim::orca::testing
