#include "crowdsim/bench/social_metrics.h"

#include <algorithm>
#include <cmath>

#include "crowdsim/kinematics.h"
#include "crowdsim/route_field.h"

namespace crowdsim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The route grid of the path-efficiency metric (the route sensor's default cell).
constexpr double kRouteResolution = 0.1;

// Angle (rad, in [0, pi]) between vectors u and d: one atan2, no wrapping.
double AngleBetween(const Vec2& u, const Vec2& d) {
  return std::atan2(std::abs(u.x() * d.y() - u.y() * d.x()), u.dot(d));
}

}  // namespace

void SocialMetricsAccumulator::Series::Add(double x) {
  sum += x;
  max = std::max(max, x);
  ++count;
}

SocialMetricsAccumulator::SocialMetricsAccumulator(double dt, bool holonomic, double goal_radius,
                                                   SocialMetricsConfig config)
    : dt_(dt),
      holonomic_(holonomic),
      goal_radius_(goal_radius),
      config_(config),
      min_ttc_(config.ttc_horizon) {}

void SocialMetricsAccumulator::Observe(const AgentState& robot, std::span<const AgentState> humans,
                                       std::span<const int> ids) {
  const Vec2& v = robot.velocity;
  const Vec2 to_goal = robot.goal - robot.position;
  const double speed_sq = v.squaredNorm();
  // Path irregularity (SocNavBench): every state's heading against its direction to the goal; a
  // holonomic robot's heading is its direction of motion, none while it stands.
  if (to_goal.squaredNorm() > 0.0) {
    if (!holonomic_) {
      turning_ += AngleBetween(Vec2(std::cos(robot.heading), std::sin(robot.heading)), to_goal);
    } else if (speed_sq > 0.0) {
      turning_ += AngleBetween(v, to_goal);
    }
  }
  double angular = 0.0;
  if (states_ > 0) {
    path_length_ += (robot.position - last_position_).norm();
    const Vec2 accel = (v - last_velocity_) / dt_;
    accel_.Add(accel.norm());
    if (states_ > 1) jerk_.Add((accel - last_accel_).norm() / dt_);
    last_accel_ = accel;
    if (!holonomic_) {
      angular = WrapAngle(robot.heading - last_heading_) / dt_;
      const double angular_accel = (angular - last_angular_) / dt_;
      angular_accel_.Add(std::abs(angular_accel));
      if (states_ > 1) angular_jerk_.Add(std::abs(angular_accel - last_angular_accel_) / dt_);
      last_angular_accel_ = angular_accel;
    }
    const bool still = speed_sq < config_.still_speed * config_.still_speed &&
                       std::abs(angular) < config_.still_angular;
    if (still && to_goal.squaredNorm() > goal_radius_ * goal_radius_) ++still_steps_;
  }
  // Proxemics between centres (squared); the zones count the steps after time 0.
  const size_t people = ids.empty() ? humans.size() : static_cast<size_t>(ids.back()) + 1;
  if (inside_personal_.size() < people) inside_personal_.resize(people, 0);
  const double personal_sq = config_.personal_radius * config_.personal_radius;
  double nearest_sq = kInf;
  for (size_t i = 0; i < humans.size(); ++i) {
    const double d_sq = (humans[i].position - robot.position).squaredNorm();
    nearest_sq = std::min(nearest_sq, d_sq);
    const bool inside = d_sq < personal_sq;
    const size_t who = ids.empty() ? i : static_cast<size_t>(ids[i]);
    if (inside && !inside_personal_[who] && states_ > 0) ++intrusions_;
    inside_personal_[who] = inside;
    min_ttc_ = std::min(min_ttc_, TimeToCollision(robot, humans[i]));
  }
  if (states_ > 0) {
    if (nearest_sq < config_.intimate_radius * config_.intimate_radius) ++intimate_steps_;
    if (nearest_sq < personal_sq) ++personal_steps_;
  }
  // Walking groups: members are consecutive runs of one group id.
  bool in_any_group = false;
  size_t group = 0;
  for (size_t first = 0; first < humans.size();) {
    size_t end = first + 1;
    if (humans[first].group >= 0) {
      while (end < humans.size() && humans[end].group == humans[first].group) ++end;
    }
    if (end - first >= 2) {
      groups_seen_ = true;
      if (inside_group_.size() <= group) inside_group_.resize(group + 1, 0);
      const bool inside = GroupSpaceContains(humans.subspan(first, end - first), robot);
      if (inside && !inside_group_[group] && states_ > 0) ++group_entries_;
      inside_group_[group] = inside;
      in_any_group = in_any_group || inside;
      ++group;
    }
    first = end;
  }
  if (states_ > 0 && in_any_group) ++group_steps_;
  last_position_ = robot.position;
  last_velocity_ = v;
  last_heading_ = robot.heading;
  last_angular_ = angular;
  ++states_;
}

SocialMetrics SocialMetricsAccumulator::Finish(bool success, double shortest_path) const {
  SocialMetrics m;
  m.shortest_path = shortest_path;
  m.spl = success ? shortest_path / std::max(path_length_, shortest_path) : 0.0;
  m.accel_mean = accel_.Mean();
  m.accel_max = accel_.max;
  m.jerk_mean = jerk_.Mean();
  m.jerk_max = jerk_.max;
  if (!holonomic_) {
    m.angular_accel_mean = angular_accel_.Mean();
    m.angular_accel_max = angular_accel_.max;
    m.angular_jerk_mean = angular_jerk_.Mean();
    m.angular_jerk_max = angular_jerk_.max;
  }
  m.path_irregularity = path_length_ > 0.0 ? turning_ / path_length_ : 0.0;
  m.freezing_time = still_steps_ * dt_;
  const int steps = states_ - 1;
  m.intimate_share = steps > 0 ? static_cast<double>(intimate_steps_) / steps : 0.0;
  m.personal_share = steps > 0 ? static_cast<double>(personal_steps_) / steps : 0.0;
  m.personal_intrusions = intrusions_;
  m.min_ttc = min_ttc_;
  if (groups_seen_) {
    m.group_intrusions = group_entries_;
    m.group_share = steps > 0 ? static_cast<double>(group_steps_) / steps : 0.0;
  }
  return m;
}

bool GroupSpaceContains(std::span<const AgentState> members, const AgentState& robot) {
  if (members.size() < 2) return false;
  Vec2 centre = Vec2::Zero();
  for (const AgentState& m : members) centre += m.position;
  centre /= static_cast<double>(members.size());
  // The space the members' bodies enclose: to the inner edge of the farthest one.
  double inner = 0.0;
  for (const AgentState& m : members)
    inner = std::max(inner, (m.position - centre).norm() - m.radius);
  const double reach = inner + robot.radius;
  return (robot.position - centre).squaredNorm() < reach * reach;
}

double TimeToCollision(const AgentState& a, const AgentState& b) {
  const Vec2 p = b.position - a.position;
  const Vec2 v = b.velocity - a.velocity;
  const double r = a.radius + b.radius;
  const double c = p.squaredNorm() - r * r;
  if (c <= 0.0) return 0.0;
  const double half_b = p.dot(v);
  const double vv = v.squaredNorm();
  if (half_b >= 0.0 || vv == 0.0) return kInf;  // apart or not closing
  const double disc = half_b * half_b - vv * c;
  if (disc < 0.0) return kInf;  // they pass without touching
  return (-half_b - std::sqrt(disc)) / vv;
}

double ShortestFreePath(const StaticMap& map, const AgentState& robot) {
  const double straight = (robot.goal - robot.position).norm();
  if (map.rectangles.empty()) return straight;
  const RouteField field(map, robot.goal, robot.radius, kRouteResolution);
  const double d = field.At(robot.position, 0.0).distance;
  return std::isfinite(d) ? std::max(d, straight) : straight;
}

}  // namespace crowdsim
