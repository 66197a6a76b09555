// Random rectangular-obstacle rooms (CrowdSim++ paper, sections 3.1 and 4.1): a square room
// closed by four wall rectangles, with N axis-aligned obstacles of random size kept a margin
// from the walls and from each other.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "crowdsim/rng.h"
#include "crowdsim/world_file.h"

namespace crowdsim::random_rect {

/// The rules of a random layout (defaults: the paper's rooms).
struct RectLayoutConfig {
  int obstacles = 1;                 ///< number of obstacles (>= 0)
  double room_size = 10.0;           ///< m; the free room is [-room_size/2, room_size/2]^2
  double wall_thickness = 0.5;       ///< m; walls lie just outside the room
  double min_side = 3.0;             ///< m; obstacle sides are uniform in [min_side, max_side]
  double max_side = 6.0;             ///< m
  double wall_margin = 1.0;          ///< m; smallest gap between an obstacle and a wall
  double obstacle_margin = 1.0;      ///< m; smallest gap between two obstacles (per axis)
  double agent_radius = 0.3;         ///< m; the disc whose free space must be connected
  double min_start_goal_dist = 7.0;  ///< m; a robot start/goal pair this far apart must exist
  double raster_resolution = 0.05;   ///< m; cell size of the connectivity check
  int max_layout_tries = 1000000;    ///< layout draws before giving up

  /// Throws std::invalid_argument naming the bad field when the rules cannot be met.
  void Validate() const;
};

/// What generation cost and produced, summed over the layouts made.
struct RectLayoutStats {
  std::int64_t layouts = 0;                ///< accepted layouts
  std::int64_t attempts = 0;               ///< layout draws (accepted + rejected)
  std::int64_t rejected_placement = 0;     ///< an obstacle had no position keeping the margins
  std::int64_t rejected_disconnected = 0;  ///< free space for the agent disc in several pieces
  std::int64_t rejected_no_pair = 0;       ///< no start/goal pair min_start_goal_dist apart
  double side_sum = 0.0;                   ///< m; sum of accepted obstacle sides (2 per obstacle)
  std::int64_t side_count = 0;

  /// Mean side length of accepted obstacles (m), 0 when none.
  double MeanSide() const { return side_count ? side_sum / side_count : 0.0; }
  /// Fraction of layout draws rejected.
  double RejectionRate() const {
    return attempts ? static_cast<double>(attempts - layouts) / attempts : 0.0;
  }
};

/// Number of wall rectangles at the front of every layout's rectangle list.
inline constexpr int kWallCount = 4;

/// The room without its walls: [-room_size/2, room_size/2]^2.
Rect RoomRegion(const RectLayoutConfig& config);
/// An empty room: bounds include the walls, rectangles are the 4 walls (bottom, top, left, right).
WorldFile EmptyRoom(const RectLayoutConfig& config, const std::string& name);

/// True if `world` keeps the free space of the agent disc in one piece and has a pair of free
/// points at least min_start_goal_dist apart (both checked on the raster).
bool LayoutIsNavigable(const WorldFile& world, const RectLayoutConfig& config,
                       RectLayoutStats* stats = nullptr);

/// Draws one valid layout (walls first, then the obstacles) from `rng`: sides uniform on the
/// millimetre grid, each obstacle's corner uniform among the millimetre positions that keep
/// the margins (a layout is redrawn when an obstacle has none), then the raster checks.
/// Adds to `stats` when not null. Throws std::runtime_error after max_layout_tries draws.
WorldFile GenerateLayout(const RectLayoutConfig& config, const std::string& name, Rng& rng,
                         RectLayoutStats* stats = nullptr);

}  // namespace crowdsim::random_rect
