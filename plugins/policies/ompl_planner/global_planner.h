// The global path: an OMPL plan in the plane for a disc among the map's rectangles,
// terminated by a sample budget so that it depends on (map, start, goal, seed) only.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "crowdsim/collision_world.h"
#include "planner_config.h"

namespace crowdsim::ompl_planner {

/// What one Plan() call found.
struct PlanResult {
  bool solved = false;
  std::vector<Vec2> path;    ///< start first, goal last (exactly); empty when not solved
  double margin = 0.0;       ///< m, the margin the path keeps (may be less than asked, README)
  int attempts = 0;          ///< planner runs (0: the straight segment was clear)
  std::int64_t samples = 0;  ///< state samples drawn, all attempts
  double length = 0.0;       ///< m
};

/// Plans on one map; immutable, so one instance may serve several threads.
class GlobalPlanner {
 public:
  /// Plans in `world` (shared, not copied); throws std::invalid_argument on bad settings.
  GlobalPlanner(std::shared_ptr<const CollisionWorld> world, PlanSettings settings);

  /// A path for a disc of `radius` from `start` to `goal`, keeping `settings.margin` more
  /// when the start and goal allow it (else margin/2, then 0). Same arguments, same path.
  PlanResult Plan(const Vec2& start, const Vec2& goal, double radius, std::uint64_t seed) const;

  /// The rectangles planned around.
  const CollisionWorld& world() const { return *world_; }
  /// The settings, as given.
  const PlanSettings& settings() const { return settings_; }

 private:
  bool Attempt(const Vec2& start, const Vec2& goal, double radius, std::int64_t budget,
               std::uint64_t seed, PlanResult* result) const;

  std::shared_ptr<const CollisionWorld> world_;
  PlanSettings settings_;
};

/// True when a disc of `radius` moves from a to b without entering a rectangle.
bool SegmentClear(const CollisionWorld& world, const Vec2& a, const Vec2& b, double radius);

/// Sum of the segment lengths.
double PathLength(const std::vector<Vec2>& path);

}  // namespace crowdsim::ompl_planner
