// Per-agent global guidance: where to head now so that ORCA's local avoidance does not stall
// behind a large obstacle. Follows a roadmap path, aiming at its farthest visible waypoint,
// and replans when the agent stops making progress along it.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "crowdsim/geometry.h"
#include "orca/roadmap.h"

namespace crowdsim::orca {

/// Where an agent should head this step.
struct GuidanceTarget {
  Vec2 point = Vec2::Zero();  ///< m, world frame
  bool is_goal = true;        ///< false for an intermediate waypoint (no slowing down there)
};

/// CrowdNav's preferred velocity towards `target`: v_pref (m/s) along the unit direction
/// when the target is an intermediate waypoint or a goal farther than 1 m, else
/// goal - position, so that the agent settles on its goal.
/// (Inline: one call per decision of every ORCA agent.)
inline Vec2 PreferredVelocity(const Vec2& position, const GuidanceTarget& target, double v_pref) {
  const Vec2 to_target = target.point - position;
  const double dist = to_target.norm();
  if (target.is_goal && dist <= 1.0) return to_target;
  if (dist <= 0.0) return Vec2::Zero();
  return to_target * (v_pref / dist);
}

/// A walking group's cohesion for an ORCA person (Moussaïd et al. 2010's threshold): farther than
/// (N - 1) / 2 m from the centre of its N members, it heads half along `pref`, half towards the
/// centre, at v_pref; else (and alone: `mates` empty) `pref` as it is.
Vec2 KeepWithGroup(const Vec2& position, const Vec2& pref, double v_pref,
                   std::span<const Vec2> mates);

/// Path-following state of one agent (one per policy instance; not shared).
class Guidance {
 public:
  /// `stall_steps` (>= 1): decisions without progress before replanning;
  /// `progress_epsilon` (m): what counts as progress along the path.
  explicit Guidance(int stall_steps = 8, double progress_epsilon = 0.05)
      : stall_steps_(stall_steps), progress_epsilon_(progress_epsilon) {}

  /// Forgets the path and switches to `roadmap` (null: head straight to the goal).
  void Reset(std::shared_ptr<const Roadmap> roadmap);

  /// Forgets the path but keeps the roadmap: the next call plans afresh from wherever the
  /// agent is then (after it stepped off its path to let others by).
  void Restart();

  /// The point to head for from `position` on the way to `goal`.
  GuidanceTarget Next(const Vec2& position, const Vec2& goal);

  const Roadmap* roadmap() const { return roadmap_.get(); }
  /// Current path (waypoints after the agent, goal last); empty when the goal is in sight.
  const std::vector<Vec2>& path() const { return path_; }
  /// Number of plans made since Reset (the first one included).
  int plans() const { return plans_; }

 private:
  void Plan(const Vec2& position, const Vec2& goal);

  int stall_steps_;
  double progress_epsilon_;
  std::shared_ptr<const Roadmap> roadmap_;
  std::vector<Vec2> path_;
  std::vector<double> remaining_;  // path length from waypoint k to the goal
  // The roadmap's capped clearance of each waypoint and of the goal, asked at every decision
  // (Roadmap::Visible), computed once per plan and per goal.
  std::vector<double> waypoint_clearance_;
  Vec2 clearance_goal_ = Vec2::Zero();
  double goal_clearance_ = -1.0;  // of clearance_goal_; < 0: not computed since Reset
  std::size_t next_ = 0;          // waypoint aimed at
  Vec2 planned_goal_ = Vec2::Zero();
  bool unreachable_ = false;  // the roadmap has no route: head straight to the goal
  double best_progress_ = kInfinity;
  int stalled_ = 0;
  int plans_ = 0;
  // The rectangle that last blocked a line of sight, tested first by the next (an agent's
  // view is blocked by the same wall decision after decision); only a hint, never an answer.
  int blocker_ = -1;
};

}  // namespace crowdsim::orca
