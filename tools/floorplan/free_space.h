// Points where an agent may stand in an imported floor plan, and start/goal pairs.
//
// A point is free when its disc of `clearance` touches no blocked cell of the navigable mask
// AND no kept rectangle: the simulation sees only the kept rectangles, the mask is the truth,
// and a start must be valid in both. Candidates come from the centre cells of the largest
// disc component, so every pair is reachable (same component).
#pragma once

#include <optional>
#include <vector>

#include "crowdsim/geometry.h"
#include "crowdsim/rng.h"
#include "crowdsim/world_file.h"
#include "grid.h"

namespace crowdsim::floorplan {

/// Geometry of a raster in the world: cell (row, col) spans x in origin.x + [col, col + 1] *
/// cell_size and y in origin.y + [height - 1 - row, height - row] * cell_size.
struct RasterFrame {
  Vec2 origin = Vec2::Zero();  ///< lower-left corner of the raster (m)
  double cell_size = 0.1;      ///< m
  int height = 0;              ///< rows

  /// Centre of cell (row, col).
  Vec2 CellCentre(int row, int col) const {
    return origin + cell_size * Vec2(col + 0.5, height - row - 0.5);
  }
  /// The cell rectangle rows row0..row1, cols col0..col1 (inclusive) in metres.
  Rect CellsToRect(int row0, int col0, int row1, int col1) const {
    return Rect::FromCorners(
        origin.x() + col0 * cell_size, origin.y() + (height - 1 - row1) * cell_size,
        origin.x() + (col1 + 1) * cell_size, origin.y() + (height - row0) * cell_size);
  }
};

/// Samples free points and pairs; immutable after construction.
class FreeSpace {
 public:
  /// `mask`: navigable cells; `centres`: candidate cells (largest component); `clearance` (m).
  FreeSpace(const Grid& mask, const Grid& centres, const RasterFrame& frame,
            std::vector<Rect> rectangles, double clearance);

  /// True when the disc at `p` misses every blocked cell (outside the raster is blocked) and
  /// every rectangle.
  bool IsFree(const Vec2& p) const;
  /// A uniform free point of the candidate cells, or nothing after `max_tries` draws.
  std::optional<Vec2> Sample(Rng& rng, int max_tries = 1000) const;
  /// `count` start/goal pairs at least `min_distance` apart; pairs equal (to 4 decimals) to
  /// one of `exclude` are redrawn, keeping train and test disjoint. Empty when impossible.
  std::vector<StartGoal> SamplePairs(int count, double min_distance, Rng& rng,
                                     const std::vector<StartGoal>& exclude = {}) const;
  /// Shortest 8-connected path length (m) between the centre cells containing a and b, over
  /// the candidate cells; a diagonal step needs both side cells. Infinity when unreachable.
  double GeodesicDistance(const Vec2& a, const Vec2& b) const;

 private:
  bool CellOf(const Vec2& p, int* row, int* col) const;

  Grid mask_;
  Grid centres_;
  RasterFrame frame_;
  std::vector<Rect> rectangles_;
  double clearance_;
  std::vector<int> candidates_;  // indices of centre cells
};

}  // namespace crowdsim::floorplan
