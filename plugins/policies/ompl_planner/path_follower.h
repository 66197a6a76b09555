// Following the global path: the farthest path point in sight, the preferred velocity
// towards it, and the progress watch that asks for a new plan.
#pragma once

#include <vector>

#include "crowdsim/collision_world.h"

namespace crowdsim::ompl_planner {

/// Progress below this (m of remaining path) does not count as progress.
inline constexpr double kProgressEpsilon = 0.05;

/// The path being followed and the watch on progress along it.
class PathFollower {
 public:
  /// A new path (start first, goal last); restarts the progress watch.
  void SetPath(std::vector<Vec2> path);
  /// Drops the path (a plan failed, a new episode).
  void Clear() { path_.clear(); }
  /// True while there is a path to follow.
  bool has_path() const { return !path_.empty(); }
  /// The path, start first, goal last.
  const std::vector<Vec2>& path() const { return path_; }

  /// Index of the farthest path point a disc of `radius` at `position` reaches in a straight
  /// line (the radius is capped by the disc's own clearance, so a robot pushed against a wall
  /// still sees along it); -1 when none is in sight (the path is blocked or left behind).
  int FarthestVisible(const CollisionWorld& world, const Vec2& position, double radius) const;

  /// Path length still to go from `position` through point `index` to the end (m).
  double Remaining(const Vec2& position, int index) const;

  /// Records one decision's remaining length; true once it has not dropped by
  /// kProgressEpsilon for `stall_steps` decisions in a row.
  bool Stalled(double remaining, int stall_steps);

 private:
  std::vector<Vec2> path_;
  std::vector<double> to_go_;  // path length from point i to the end
  double best_remaining_ = kInfinity;
  int steps_without_progress_ = 0;
};

/// Preferred velocity towards `target`: v_pref along the direction, slowing on the last step
/// only when the target is the goal (so the robot stops on it instead of overshooting).
Vec2 PreferredVelocity(const Vec2& position, const Vec2& target, bool is_goal, double v_pref,
                       double time_step);

}  // namespace crowdsim::ompl_planner
