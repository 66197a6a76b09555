#include "path_follower.h"

#include <algorithm>

namespace crowdsim::ompl_planner {

void PathFollower::SetPath(std::vector<Vec2> path) {
  path_ = std::move(path);
  to_go_.assign(path_.size(), 0.0);
  for (int i = static_cast<int>(path_.size()) - 2; i >= 0; --i) {
    to_go_[i] = to_go_[i + 1] + (path_[i + 1] - path_[i]).norm();
  }
  best_remaining_ = kInfinity;
  steps_without_progress_ = 0;
}

int PathFollower::FarthestVisible(const CollisionWorld& world, const Vec2& position,
                                  double radius) const {
  // A sweep that starts overlapping reports contact at once; shrink to the clearance.
  const double clearance = world.ClearanceAt(position, radius + 1.0);
  const double r = std::min(radius, clearance - 1e-6);
  if (r <= 0.0) return -1;
  for (int i = static_cast<int>(path_.size()) - 1; i >= 0; --i) {
    if (world.SweepDisc(position, path_[i], r).fraction == kInfinity) return i;
  }
  return -1;
}

double PathFollower::Remaining(const Vec2& position, int index) const {
  return (path_[index] - position).norm() + to_go_[index];
}

bool PathFollower::Stalled(double remaining, int stall_steps) {
  if (remaining < best_remaining_ - kProgressEpsilon) {
    best_remaining_ = remaining;
    steps_without_progress_ = 0;
    return false;
  }
  return ++steps_without_progress_ >= stall_steps;
}

Vec2 PreferredVelocity(const Vec2& position, const Vec2& target, bool is_goal, double v_pref,
                       double time_step) {
  const Vec2 d = target - position;
  const double dist = d.norm();
  if (dist < 1e-9) return Vec2::Zero();
  double speed = v_pref;
  if (is_goal && time_step > 0.0) speed = std::min(speed, dist / time_step);
  return d / dist * speed;
}

}  // namespace crowdsim::ompl_planner
