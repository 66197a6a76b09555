#include "crowdsim/kinematics.h"

#include <algorithm>
#include <cmath>

namespace crowdsim {

const char* KinematicsModelName(KinematicsModel m) {
  switch (m) {
    case KinematicsModel::kHolonomic:
      return "holonomic";
    case KinematicsModel::kUnicycle:
      return "unicycle";
    case KinematicsModel::kDiffDrive:
      return "diff_drive";
  }
  return "unknown";
}

bool ParseKinematicsModel(std::string_view name, KinematicsModel* out) {
  for (KinematicsModel m :
       {KinematicsModel::kHolonomic, KinematicsModel::kUnicycle, KinematicsModel::kDiffDrive}) {
    if (name == KinematicsModelName(m)) {
      *out = m;
      return true;
    }
  }
  return false;
}

double WrapAngle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a == -std::numbers::pi ? std::numbers::pi : a;
}

namespace {

// `want` moved at most `step` from `from` (step may be infinite).
double Slew(double want, double from, double step) {
  return std::clamp(want, from - step, from + step);
}

}  // namespace

ExecutedMove ExecuteAction(const RobotKinematics& k, double v_pref, const RobotMotion& motion,
                           const Action& action, double dt) {
  ExecutedMove m;
  if (k.Holonomic()) {
    m.velocity = action.velocity;
    // The change of velocity is clipped as a vector: direction kept, length a*dt at most.
    const Vec2 change = m.velocity - motion.velocity;
    const double reach = k.accel_max * dt;
    if (NormAbove(change, reach)) m.velocity = motion.velocity + change * (reach / change.norm());
    m.heading = motion.heading;
    return m;
  }
  m.linear = std::clamp(Slew(action.linear, motion.linear, k.accel_max * dt), -v_pref, v_pref);
  m.angular = std::clamp(Slew(action.angular, motion.angular, k.angular_accel_max * dt),
                         -k.angular_speed_max, k.angular_speed_max);
  const double turn = m.angular * dt;
  m.heading = WrapAngle(motion.heading + turn);
  if (k.model == KinematicsModel::kUnicycle || std::abs(turn) < 1e-9) {
    // CrowdNav's unicycle: turn first, then move straight along the new heading.
    const double h = k.model == KinematicsModel::kUnicycle ? motion.heading + turn : motion.heading;
    m.velocity = m.linear * Vec2(std::cos(h), std::sin(h));
    return m;
  }
  // Exact arc of radius linear/angular: its chord over dt.
  const double r = m.linear / m.angular;
  const double h0 = motion.heading;
  const double h1 = h0 + turn;
  m.velocity = Vec2(r * (std::sin(h1) - std::sin(h0)), r * (std::cos(h0) - std::cos(h1))) / dt;
  return m;
}

Action TrackVelocity(const RobotKinematics& k, const RobotMotion& motion, const Vec2& velocity,
                     double dt) {
  const double speed = velocity.norm();
  if (speed == 0.0) return Action::Command(0.0, 0.0);
  const double error = WrapAngle(std::atan2(velocity.y(), velocity.x()) - motion.heading);
  const double turn_max = k.angular_speed_max * dt;
  const double turn = std::clamp(error, -turn_max, turn_max);
  // The direction moved: the new heading (unicycle) or the chord's, halfway (arc).
  const double moved = k.model == KinematicsModel::kDiffDrive ? error - turn / 2.0 : error - turn;
  const double c = std::cos(moved);
  return Action::Command(c > 0.0 ? speed * c : 0.0, turn / dt);
}

}  // namespace crowdsim
