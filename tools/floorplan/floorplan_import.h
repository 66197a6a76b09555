// Floor plan image -> world file: the import pipeline (README.md, "Pipeline").
//
//   image -> binary (white/transparent navigable) -> 0.1 m cells (area rule)
//   outline maps: exterior = flood fill from the border on a copy whose door-sized gaps are
//                 closed; exterior marked blocked
//   closing x2 (3x3) of the navigable area (outline maps: filling specks only, walls stay)
//   largest component for a 0.3 m disc -> navigable mask (everything else blocked)
//   crop to the mask + margin -> exact greedy rectangles of the blocked area, keep N largest
//   sample test pairs, disjoint train pairs, free points; statistics.
//   The world file carries the navigable mask (its `mask:` section), so renders draw it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "crowdsim/world_file.h"
#include "free_space.h"
#include "grid.h"

namespace crowdsim::floorplan {

/// How the image draws the building.
enum class PlanKind {
  kAuto,     ///< navmesh for *_0.1m.png, else outline
  kNavmesh,  ///< navigable area filled white, everything else black (HM3D rasters)
  kOutline,  ///< obstacle outlines black on white, inside and outside alike (Gibson maps)
};

/// Parameters of one import (defaults: the values documented in README.md).
struct ImportOptions {
  PlanKind kind = PlanKind::kAuto;
  double source_resolution = 0.0;  ///< m/px of the image; 0 = maps_metadata or 0.1 (navmesh)
  double cell_size = 0.1;          ///< m per simulation cell (paper: 0.1)
  int max_rectangles = 30;         ///< rectangles kept, largest first (paper: 30), >= 1
  std::uint64_t seed = 1;          ///< sampling seed
  int test_pairs = 500;            ///< robot start/goal pairs of the test split
  int train_pairs = 500;           ///< robot pairs of the train split (disjoint from test)
  int free_points = 400;           ///< free points for placing humans
  double agent_radius = 0.3;       ///< m; disc that must pass for the component (robot 0.3)
  double clearance = 0.3;          ///< m; free distance around starts, goals, free points
  double min_pair_distance = 5.0;  ///< m; capped at half the component's longer side
  double door_gap = 1.0;           ///< m; gaps up to this width closed to find the exterior
  double margin = 0.5;             ///< m of blocked border kept around the navigable mask
  std::string name;                ///< world name; empty = the image's file stem
  std::string attribution;         ///< empty = derived from the source folder
};

/// One import: the world file and what the report, the preview and the dataset need.
struct ImportResult {
  WorldFile world;                     ///< world.mask holds `mask` (the one sampled from)
  PlanKind kind = PlanKind::kOutline;  ///< the resolved kind
  double source_resolution = 0.0;      ///< m/px used
  Grid mask;                           ///< navigable mask of the world (cropped)
  RasterFrame frame;                   ///< where `mask` lies in world coordinates
  double seconds = 0.0;                ///< wall time of the import
};

/// Imports one floor-plan image. Throws FloorplanError naming the file and the fix (bad
/// image, unknown resolution, nothing navigable, no component for the agent, too few pairs).
ImportResult ImportFloorplan(const std::filesystem::path& image, const ImportOptions& options);

/// Metres per pixel from maps_metadata/<stem>.yaml next to the image's maps/ folder (Gibson
/// layout); 0 when there is no such file. Throws FloorplanError when it exists but is bad.
double MetadataResolution(const std::filesystem::path& image);

/// The world-file form of a navigable mask lying at `frame` (cell size = resolution).
std::shared_ptr<const NavigableMask> ToNavigableMask(const Grid& mask, const RasterFrame& frame);

/// Value of stat `key` in `world` (throws FloorplanError when absent).
double StatValue(const WorldFile& world, const std::string& key);

}  // namespace crowdsim::floorplan
