// The social navigation metrics of an episode (Francis et al. 2023): path efficiency, motion
// quality, proxemics and time to collision, from the states of its steps. One accumulator serves
// the runner and every other reader of steps, so both give the same numbers (docs/metrics.md).
#pragma once

#include <limits>
#include <span>
#include <vector>

#include "crowdsim/agent_state.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

/// One episode's social navigation metrics; NaN where a metric does not apply.
struct SocialMetrics {
  double shortest_path = 0.0;  ///< m; shortest free path start -> goal for the robot's disc
  double spl = 0.0;            ///< success * shortest_path / max(path length, shortest_path)
  double accel_mean = 0.0;     ///< m/s^2; mean over steps of |v_k - v_k-1| / dt
  double accel_max = 0.0;
  double jerk_mean = 0.0;  ///< m/s^3; mean over steps of |a_k - a_k-1| / dt
  double jerk_max = 0.0;
  /// rad/s^2 and rad/s^3, from the heading; NaN for a holonomic robot (it has none).
  double angular_accel_mean = std::numeric_limits<double>::quiet_NaN();
  double angular_accel_max = std::numeric_limits<double>::quiet_NaN();
  double angular_jerk_mean = std::numeric_limits<double>::quiet_NaN();
  double angular_jerk_max = std::numeric_limits<double>::quiet_NaN();
  double path_irregularity = 0.0;  ///< rad/m; summed angle heading-to-goal / path length
  double freezing_time = 0.0;      ///< s; still while not at the goal
  double intimate_share = 0.0;     ///< share of the steps with a person within intimate_radius
  double personal_share = 0.0;     ///< share of the steps with a person within personal_radius
  double personal_intrusions = 0;  ///< entries of a person into the personal zone after time 0
  double min_ttc = 5.0;  ///< s; constant-velocity TTC, at most SocialMetricsConfig::ttc_horizon
  /// The robot in a walking group's space (GroupSpaceContains): entries after time 0, and the
  /// share of the steps. NaN when no group of two or more walks in the episode.
  double group_intrusions = std::numeric_limits<double>::quiet_NaN();
  double group_share = std::numeric_limits<double>::quiet_NaN();
  /// The robot's effect on the people (people_effect.h), means over people of (with the robot -
  /// without it): how much farther from their goals they end (m), path walked (m) and mean
  /// acceleration (m/s^2). NaN without people, or when not computed.
  double people_lost_progress = std::numeric_limits<double>::quiet_NaN();
  double people_path_added = std::numeric_limits<double>::quiet_NaN();
  double people_accel_added = std::numeric_limits<double>::quiet_NaN();
};

/// Whether the robot's disc reaches into a group's space: the circle around its members' centre
/// out to the inner edge of the farthest member's disc (the o-space of Kendon's F-formation, as a
/// circle). A robot at a conversational circle's open place, as far out as the members, is not in.
bool GroupSpaceContains(std::span<const AgentState> members, const AgentState& robot);

/// Radii and thresholds (docs/metrics.md cites each).
struct SocialMetricsConfig {
  double intimate_radius = 0.45;  ///< m between centres (Hall 1966)
  double personal_radius = 1.2;   ///< m between centres (Hall 1966)
  double still_speed = 0.01;      ///< m/s: below it the robot stands (HuNavSim)
  double still_angular = 0.02;    ///< rad/s: and turns no faster (HuNavSim)
  double ttc_horizon = 5.0;       ///< s: longer TTCs count as this (CrowdNav's ORCA time_horizon)
};

/// Accumulates SocialMetrics over an episode's states: the first Observe is time 0, each next one
/// the state after a step of `dt` (positions, the velocities moved with, the robot's heading).
class SocialMetricsAccumulator {
 public:
  /// `holonomic`: the robot has no body heading (its path irregularity uses its direction of
  /// motion; angular metrics are NaN).
  SocialMetricsAccumulator(double dt, bool holonomic, double goal_radius,
                           SocialMetricsConfig config = {});

  /// `ids`: each of `humans`' scenario index when only the present are given (empty: humans[i]
  /// is human i), so a person's zone state follows the person.
  void Observe(const AgentState& robot, std::span<const AgentState> humans,
               std::span<const int> ids = {});

  /// The metrics; `shortest_path` as ShortestFreePath gives it.
  SocialMetrics Finish(bool success, double shortest_path) const;

 private:
  struct Series {
    double sum = 0.0;
    double max = 0.0;
    int count = 0;
    void Add(double x);
    double Mean() const { return count > 0 ? sum / count : 0.0; }
  };

  double dt_;
  bool holonomic_;
  double goal_radius_;
  SocialMetricsConfig config_;

  int states_ = 0;
  Vec2 last_position_ = Vec2::Zero();
  Vec2 last_velocity_ = Vec2::Zero();
  Vec2 last_accel_ = Vec2::Zero();
  double last_heading_ = 0.0;
  double last_angular_ = 0.0;
  double last_angular_accel_ = 0.0;
  double path_length_ = 0.0;
  double turning_ = 0.0;  // sum of the angles between heading and goal direction
  Series accel_, jerk_, angular_accel_, angular_jerk_;
  int still_steps_ = 0;
  int intimate_steps_ = 0;
  int personal_steps_ = 0;
  int intrusions_ = 0;
  std::vector<unsigned char> inside_personal_;  // per person, within personal_radius
  double min_ttc_;
  bool groups_seen_ = false;
  int group_steps_ = 0;
  int group_entries_ = 0;
  std::vector<unsigned char> inside_group_;  // per group, in list order
};

/// Time until two discs touch, each keeping its velocity: 0 when they overlap, infinity when they
/// never meet.
double TimeToCollision(const AgentState& a, const AgentState& b);

/// The shortest free path (m) from the robot's start to its goal for its disc, around the map's
/// rectangles on a 0.1 m route grid; the straight line when the grid finds none.
double ShortestFreePath(const StaticMap& map, const AgentState& robot);

}  // namespace crowdsim
