#include "orca/guidance.h"

namespace crowdsim::orca {

void Guidance::Reset(std::shared_ptr<const Roadmap> roadmap) {
  roadmap_ = std::move(roadmap);
  Restart();
  plans_ = 0;
  goal_clearance_ = -1.0;
  blocker_ = -1;
}

void Guidance::Restart() {
  path_.clear();
  remaining_.clear();
  waypoint_clearance_.clear();
  next_ = 0;
  unreachable_ = false;
  best_progress_ = kInfinity;
  stalled_ = 0;
}

void Guidance::Plan(const Vec2& position, const Vec2& goal) {
  ++plans_;
  planned_goal_ = goal;
  path_ = roadmap_->ShortestPath(position, goal);
  unreachable_ = path_.empty();
  remaining_.assign(path_.size(), 0.0);
  for (std::size_t k = path_.size(); k-- > 1;) {
    remaining_[k - 1] = remaining_[k] + (path_[k] - path_[k - 1]).norm();
  }
  waypoint_clearance_.clear();
  for (const Vec2& w : path_) waypoint_clearance_.push_back(roadmap_->CappedClearance(w));
  next_ = 0;
  best_progress_ = kInfinity;
  stalled_ = 0;
}

GuidanceTarget Guidance::Next(const Vec2& position, const Vec2& goal) {
  if (!roadmap_) return {goal, true};
  const double here = roadmap_->CappedClearance(position);
  if (goal_clearance_ < 0.0 || goal != clearance_goal_) {
    clearance_goal_ = goal;
    goal_clearance_ = roadmap_->CappedClearance(goal);
  }
  // The common case in open space: nothing to plan.
  if (roadmap_->Visible(position, here, goal, goal_clearance_, &blocker_)) {
    path_.clear();
    waypoint_clearance_.clear();
    unreachable_ = false;
    return {goal, true};
  }
  if ((path_.empty() && !unreachable_) || goal != planned_goal_) {
    Plan(position, goal);
  } else if (unreachable_ && ++stalled_ >= stall_steps_) {
    Plan(position, goal);  // moved since: maybe the roadmap connects it now
  }
  if (unreachable_) return {goal, true};  // ORCA alone, sliding along the obstacles

  // Aim at the farthest waypoint still in sight; lose sight of all of them (pushed away by
  // others) and the path is planned again from here.
  auto farthest_visible = [&]() -> std::ptrdiff_t {
    for (std::size_t k = path_.size(); k-- > next_;) {
      if (roadmap_->Visible(position, here, path_[k], waypoint_clearance_[k], &blocker_)) {
        return static_cast<std::ptrdiff_t>(k);
      }
    }
    return -1;
  };
  std::ptrdiff_t k = farthest_visible();
  if (k < 0) {
    Plan(position, goal);
    if (unreachable_) return {goal, true};
    k = farthest_visible();
    if (k < 0) k = 0;  // the plan starts at a node the agent sees; only rounding lands here
  }
  next_ = static_cast<std::size_t>(k);

  // Progress = path length still to go; none for stall_steps decisions means the agent is
  // stuck (crowded corner, pushed off the path): plan again from where it is.
  const double progress = (path_[next_] - position).norm() + remaining_[next_];
  if (progress < best_progress_ - progress_epsilon_) {
    best_progress_ = progress;
    stalled_ = 0;
  } else if (++stalled_ >= stall_steps_) {
    Plan(position, goal);
    if (unreachable_) return {goal, true};
    next_ = 0;
  }
  return {path_[next_], next_ + 1 == path_.size()};
}

Vec2 KeepWithGroup(const Vec2& position, const Vec2& pref, double v_pref,
                   std::span<const Vec2> mates) {
  if (mates.empty()) return pref;
  Vec2 centre = position;
  for (const Vec2& q : mates) centre += q;
  const double n = static_cast<double>(mates.size()) + 1.0;
  const Vec2 to_centre = centre / n - position;
  const double d = to_centre.norm();
  if (d <= 0.5 * (n - 1.0)) return pref;
  const double speed = pref.norm();
  const Vec2 towards = (speed > 0.0 ? Vec2(pref / speed) : Vec2::Zero()) + 2.0 * to_centre / d;
  const double norm = towards.norm();
  return norm > 0.0 ? Vec2(towards * (v_pref / norm)) : pref;
}

}  // namespace crowdsim::orca
