// ORCA (optimal reciprocal collision avoidance, van den Berg et al.) for one agent: the new
// velocity closest to the preferred one that keeps it clear of its neighbours (each side
// taking half of the avoidance) and of the static obstacles (taking all of it).
#pragma once

#include <span>
#include <vector>

#include "crowdsim/geometry.h"
#include "orca/linear_program.h"
#include "orca/obstacles.h"

namespace crowdsim::orca {

/// An agent as the solver sees it (world frame).
struct OrcaAgent {
  Vec2 position = Vec2::Zero();  ///< m
  Vec2 velocity = Vec2::Zero();  ///< m/s, current
  double radius = 0.3;           ///< m, the radius kept clear (any padding included)
};

/// RVO2's per-agent settings, less the neighbour search (the caller picks the neighbours).
struct OrcaParams {
  double time_horizon = 5.0;       ///< s (> 0): how far ahead agent collisions are avoided
  double time_horizon_obst = 5.0;  ///< s (> 0): the same for obstacles
  double max_speed = 1.0;          ///< m/s (>= 0): the new velocity never exceeds it
};

/// Range (m) within which obstacle edges matter to an agent: RVO2's
/// time_horizon_obst * max_speed + radius.
inline double ObstacleRange(const OrcaParams& params, double radius) {
  return params.time_horizon_obst * params.max_speed + radius;
}

/// The ORCA lines of `self` (obstacle lines first), as computed for one decision; exposed for
/// tests and tools. `num_obstacle_lines` receives how many come from obstacles.
void BuildOrcaLines(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                    const OrcaObstacles& obstacles, const OrcaParams& params, double time_step,
                    std::vector<OrcaLine>* lines, std::size_t* num_obstacle_lines);

/// How one solve went (for tests and diagnostics).
struct OrcaSolveInfo {
  std::size_t num_lines = 0;           ///< ORCA lines, obstacles included
  std::size_t num_obstacle_lines = 0;  ///< lines from obstacles (always kept hard)
  /// False when the agent lines could not all hold together: the result then minimises
  /// their largest violation, and ORCA no longer guarantees freedom from collision.
  bool feasible = true;
};

/// What a solve gathers and drops (reused, so that a solve allocates nothing).
struct OrcaSolveScratch {
  std::vector<ObstacleNeighbor> near;
  std::vector<OrcaLine> lines;
};

/// The new velocity (m/s) of `self`. `neighbours` nearest first (RVO2 keeps the 10 nearest
/// within 10-15 m); `time_step` (s, > 0) sets how fast overlapping agents separate. Uses a
/// scratch of the calling thread.
Vec2 ComputeOrcaVelocity(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                         const OrcaObstacles& obstacles, const OrcaParams& params,
                         const Vec2& pref_velocity, double time_step,
                         OrcaSolveInfo* info = nullptr);

/// The same with the caller's scratch: a caller that keeps one (a policy's per-thread
/// scratch) spares the thread-local lookups, which cost calls in a plugin.
Vec2 ComputeOrcaVelocity(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                         const OrcaObstacles& obstacles, const OrcaParams& params,
                         const Vec2& pref_velocity, double time_step, OrcaSolveScratch* scratch,
                         OrcaSolveInfo* info = nullptr);

}  // namespace crowdsim::orca
