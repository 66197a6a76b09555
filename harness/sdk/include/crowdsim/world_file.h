// The world file (YAML): one static layout with optional precomputed start/goal pairs and
// free points, written by the generators/importers and read by world plugins.
//
//   format: crowdsim-world/1
//   name: rect1_test_007
//   attribution: "..."              # source credit (floor plans)
//   bounds: [xmin, ymin, xmax, ymax]
//   rectangles: [[xmin, ymin, xmax, ymax], ...]
//   robot_pairs: {train: [[sx, sy, gx, gy], ...], test: [...]}   # in bounds, in no rectangle
//   free_points: [[x, y], ...]      # sampled free space for humans (floor plans)
//   stats: {free_area_m2: 61.2, ...}
//   mask:                           # optional navigable raster (floor plans), see below
//     resolution: 0.1000            # m per cell
//     origin: [x, y]                # lower-left corner of the raster (m)
//     width: W
//     height: H
//     rows:                         # H strings, the first is the top row (max y)
//       - "5 12 3 7"
//
// Mask rows are run lengths: whole numbers separated by single spaces that alternate blocked,
// navigable, blocked, ... starting with blocked (the first run is 0 when the row starts
// navigable; no other run is 0) and sum to W. "5 12 3 7" with W = 27 is 5 blocked cells, 12
// navigable, 3 blocked, 7 navigable. A fully blocked row is "W".
//
// A world set file holds many layouts: `format: crowdsim-world-set/1`, `worlds: [<world>...]`.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

class CROWDSIM_SDK_API WorldFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CROWDSIM_SDK_API StartGoal {
  Vec2 start = Vec2::Zero();
  Vec2 goal = Vec2::Zero();
};

struct CROWDSIM_SDK_API WorldFile {
  std::string name;
  std::string attribution;
  Rect bounds;
  std::vector<Rect> rectangles;
  std::vector<StartGoal> train_pairs;
  std::vector<StartGoal> test_pairs;
  std::vector<Vec2> free_points;
  std::vector<std::pair<std::string, double>> stats;  ///< in file order
  std::shared_ptr<const NavigableMask> mask;  ///< navigable raster (floor plans); may be null

  /// The static map of this world (rectangles, bounds and the mask when there is one).
  StaticMap ToStaticMap() const;
};

/// Reads one world; throws WorldFileError naming the file, line and key.
CROWDSIM_SDK_API WorldFile ReadWorldFile(const std::filesystem::path& path);
/// Reads a world set; throws WorldFileError.
CROWDSIM_SDK_API std::vector<WorldFile> ReadWorldSet(const std::filesystem::path& path);

/// Writes byte-stable YAML (4 decimals): regenerating gives identical files. Throws WorldFileError.
CROWDSIM_SDK_API void WriteWorldFile(const WorldFile& world, const std::filesystem::path& path);
CROWDSIM_SDK_API void WriteWorldSet(const std::vector<WorldFile>& worlds,
                                    const std::string& comment, const std::filesystem::path& path);

}  // namespace crowdsim
