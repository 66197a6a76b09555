#include "crowdsim/bench/people_effect.h"

namespace crowdsim {

void PeopleWalks::Observe(std::span<const AgentState> humans) {
  if (last.empty()) {
    path.assign(humans.size(), 0.0);
    accel_sum.assign(humans.size(), 0.0);
  } else {
    for (size_t i = 0; i < humans.size(); ++i) {
      path[i] += (humans[i].position - last[i].position).norm();
      accel_sum[i] += (humans[i].velocity - last[i].velocity).norm() / dt_;
    }
    ++steps;
  }
  last.assign(humans.begin(), humans.end());
  // People start from rest: the first step's change is from zero.
  if (steps == 0)
    for (AgentState& h : last) h.velocity = Vec2::Zero();
}

void FillPeopleEffect(const Episode& played, const PeopleWalks& with, SocialMetrics* m) {
  const size_t n = with.last.size();
  if (n == 0 || with.steps == 0) return;
  SimConfig sim = played.sim();
  sim.robot_visible = false;  // people who never see the robot: the world without it
  PeopleWalks without(sim.time_step);
  try {
    Episode replay(played.scenario(), sim, played.agents());
    if (replay.done()) return;  // a policy's Reset failed
    without.Observe(replay.humans());
    for (int k = 0; k < with.steps; ++k) {
      replay.StepPeopleOnly();
      without.Observe(replay.humans());
    }
  } catch (const AbortRun&) {
    throw;
  } catch (const std::exception&) {
    return;  // not computable: left NaN
  }
  double lost = 0.0, path = 0.0, accel = 0.0;
  for (size_t i = 0; i < n; ++i) {
    // Progress towards the goal the person heads for in the world without the robot.
    const Vec2& goal = without.last[i].goal;
    lost += (with.last[i].position - goal).norm() - (without.last[i].position - goal).norm();
    path += with.path[i] - without.path[i];
    accel += (with.accel_sum[i] - without.accel_sum[i]) / with.steps;
  }
  m->people_lost_progress = lost / static_cast<double>(n);
  m->people_path_added = path / static_cast<double>(n);
  m->people_accel_added = accel / static_cast<double>(n);
}

}  // namespace crowdsim
