// The robot's motion model: how an action moves it (holonomic, unicycle, differential drive).
#pragma once

#include <numbers>
#include <string_view>

#include "crowdsim/action.h"
#include "crowdsim/export.h"
#include "crowdsim/geometry.h"

namespace crowdsim {

/// kHolonomic: the velocity changes at will (CrowdSim++). kUnicycle: CrowdNav's unicycle, turn
/// then move straight. kDiffDrive: (linear, angular) held over the step, exact arc.
enum class KinematicsModel { kHolonomic, kUnicycle, kDiffDrive };

/// The suite name of a model ("holonomic", "unicycle", "diff_drive").
CROWDSIM_SDK_API const char* KinematicsModelName(KinematicsModel m);
/// The model a suite name means; false when it names none.
CROWDSIM_SDK_API bool ParseKinematicsModel(std::string_view name, KinematicsModel* out);

/// How the robot moves: a row's `kinematics:` (docs/kinematics.md). The default is the paper's
/// holonomic disc without limits.
struct CROWDSIM_SDK_API RobotKinematics {
  KinematicsModel model = KinematicsModel::kHolonomic;
  /// rad/s; pi is CrowdNav's largest rotation, pi/4 per 0.25 s step. Non-holonomic models only.
  double angular_speed_max = std::numbers::pi;
  double accel_max = kInfinity;          ///< m/s^2; holonomic: on the velocity vector's change
  double angular_accel_max = kInfinity;  ///< rad/s^2; non-holonomic models only
  /// A velocity-only policy may drive a non-holonomic robot through TrackVelocity (suite key
  /// `track_velocity: true`; built-in policies that ask for it need not).
  bool track_velocity = false;

  bool Holonomic() const { return model == KinematicsModel::kHolonomic; }
  /// The paper's robot: holonomic without an acceleration limit.
  bool Unconstrained() const { return Holonomic() && accel_max == kInfinity; }
};

/// The robot's motion before a step, what the limits act on.
struct CROWDSIM_SDK_API RobotMotion {
  Vec2 velocity = Vec2::Zero();  ///< m/s, world frame
  double heading = 0.0;          ///< rad
  double linear = 0.0;           ///< m/s along the heading (non-holonomic)
  double angular = 0.0;          ///< rad/s (non-holonomic)
};

/// What one step executes after the limits.
struct CROWDSIM_SDK_API ExecutedMove {
  Vec2 velocity = Vec2::Zero();  ///< displacement / dt: what moves the robot and is swept
  double heading = 0.0;          ///< rad after the step
  double linear = 0.0;           ///< m/s, executed (holonomic: 0)
  double angular = 0.0;          ///< rad/s, executed (holonomic: 0)
};

/// Executes `action` for `dt` s from `motion`. Holonomic takes action.velocity; the others take a
/// command (Action::Command). Commands are clipped: |linear| <= v_pref, |angular| <=
/// angular_speed_max, and changes to accel_max * dt and angular_accel_max * dt.
CROWDSIM_SDK_API ExecutedMove ExecuteAction(const RobotKinematics& k, double v_pref,
                                            const RobotMotion& motion, const Action& action,
                                            double dt);

/// Turn-then-go tracking of a world velocity by a non-holonomic robot: turn towards it as far as
/// angular_speed_max allows, then move at its speed projected on the new heading (none past 90
/// degrees). A zero velocity stops without turning.
CROWDSIM_SDK_API Action TrackVelocity(const RobotKinematics& k, const RobotMotion& motion,
                                      const Vec2& velocity, double dt);

/// `a` wrapped to (-pi, pi].
CROWDSIM_SDK_API double WrapAngle(double a);

}  // namespace crowdsim
