// The discrete local planner: among 16 velocities (2 speeds x 8 directions, turned so that
// direction 0 is the preferred one) pick the one closest to the preferred velocity that keeps
// a swept distance from every person's constant-velocity prediction.
#pragma once

#include <span>
#include <vector>

#include "crowdsim/collision_world.h"
#include "crowdsim/sim_config.h"
#include "orca/solver.h"

namespace crowdsim::ompl_planner {

/// Settings of one choice.
struct ActionSetParams {
  double v_pref = SimConfig{}.robot_v_pref;  ///< m/s; the speeds are v_pref and v_pref / 2
  double radius = SimConfig{}.robot_radius;  ///< m, the robot's
  double time_step = SimConfig{}.time_step;  ///< s the action is held
  double horizon = 1.0;                      ///< s of prediction checked (at least one time step)
  double clearance = 0.1;  ///< m of surface distance to keep from every prediction
};

/// The 16 candidate velocities: speeds {v_pref, v_pref / 2} times the unit vectors at
/// k * 45 degrees from `pref` (from +x when `pref` is zero).
std::vector<Vec2> ActionSet(const Vec2& pref, double v_pref);

/// Smallest surface distance over [0, horizon] between the robot moving from `position` at
/// `velocity` and `person` moving at its own velocity (negative: they overlap).
double PredictedDistance(const Vec2& position, const Vec2& velocity, double radius,
                         const orca::OrcaAgent& person, double horizon);

/// The chosen velocity: `pref` itself if safe, else the safe candidate closest to `pref`,
/// else (nothing safe) the candidate, standing still included, that keeps the largest
/// predicted distance. A candidate is safe when it keeps `clearance` from every person over
/// the horizon and its step does not enter a rectangle.
Vec2 ChooseAction(const Vec2& position, const Vec2& pref, std::span<const orca::OrcaAgent> people,
                  const CollisionWorld& world, const ActionSetParams& params);

}  // namespace crowdsim::ompl_planner
